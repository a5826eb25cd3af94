"""Debian's python3-numpy, -scipy and -matplotlib are installed for /usr/bin/python3, and CMake may find
another python3 first (a pyenv shim, a virtualenv). A test script calls ensure() before importing them: if
this interpreter lacks one, the script is run again, with the same arguments, under Debian's."""
import importlib
import os
import sys

SYSTEM = "/usr/bin/python3"


def ensure(*modules):
    try:
        for module in modules:
            importlib.import_module(module)
    except ImportError:
        script = os.path.abspath(sys.argv[0])
        if os.path.exists(SYSTEM) and os.path.realpath(sys.executable) != os.path.realpath(SYSTEM):
            os.execv(SYSTEM, [SYSTEM, script] + sys.argv[1:])
        raise
