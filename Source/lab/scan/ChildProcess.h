#pragma once
// Runs a helper program (the figure scripts) from an argument vector, never through a shell, so that a path
// with quotes, spaces, $(...) or newlines reaches the program as one argument and runs nothing else
//. POSIX posix_spawnp: the program is looked up on PATH like a shell would.
#include <string>
#include <vector>

namespace rosin::scan
{

/// Runs argv[0] with argv and waits. Returns its exit status, or -1 if it could not be started or did not
/// exit normally. With `quiet`, its standard output and error go to /dev/null.
int runProgram(const std::vector<std::string>& argv, bool quiet = false);

/// True if `program` names an executable file, directly or on PATH.
bool programAvailable(const std::string& program);

/// The Python that draws Rosin's figures: the first of $ROSIN_PYTHON, /usr/bin/python3 (where
/// .ci/install-deps puts Debian's matplotlib) and python3 on PATH that imports matplotlib and numpy. Empty if
/// none does. Looked up once per process (it starts each candidate).
const std::string& figurePython();
/// The candidates figurePython() tries, in order, for messages.
std::string figurePythonCandidates();

} // namespace rosin::scan
