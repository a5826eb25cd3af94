#include "cli/Dispatcher.h"

#include <cstdio>
#include <exception>

#include "cli/CommandLine.h"
#include "cli/Commands.h"
#include "cli/ManPage.h"
#include "cli/ShellCompletion.h"
#include "core/physics/modal/SimdLevel.h"

#ifndef ROSIN_VERSION
#define ROSIN_VERSION "unknown"
#endif

namespace rosin::cli
{

namespace
{
/// `rosin --parse-only COMMAND ...`: the command's parser on the arguments, nothing run.
int parseOnly(const std::vector<std::string>& args, std::ostream& out, std::ostream& err)
{
    const Command* command = args.empty() ? nullptr : findCommand(args.front());
    if (command == nullptr)
    {
        err << "error: --parse-only: expected a command ("
            << (args.empty() ? "none" : "\"" + args.front() + "\"") << " given)\n";
        return kExitUsageError;
    }
    try
    {
        command->check({args.begin() + 1, args.end()});
    }
    catch (const std::exception& e)
    {
        err << "error: " << e.what() << "\nsee 'rosin " << command->name << " --help'\n";
        return kExitUsageError;
    }
    out << "rosin " << command->name << ": the options are accepted\n";
    return kExitOk;
}
} // namespace

std::string usage()
{
    std::string text =
        "rosin " ROSIN_VERSION " - physically modelled bowed string\n"
        "\n"
        "usage: rosin COMMAND [options]\n"
        "       rosin COMMAND --help     options of one command\n"
        "       rosin --help | --version\n"
        "       rosin --man | --completion bash  the man page, the bash completion script\n"
        "       rosin --parse-only COMMAND [options]  check a command line without running it\n"
        "\n"
        "commands:\n";
    for (const Command& c : commands())
    {
        char line[200];
        std::snprintf(line, sizeof(line), "  %-10s %s\n", c.name, c.summary);
        text += line;
    }
    text += "\n"
            "All quantities are SI (N, m, s, m/s). Errors name the file or option, the field and what was\n"
            "expected.\n"
            "exit status: 0 success, 1 bad value, file or preset (or a failed render), 2 usage error,\n"
            "128+signal for a scan stopped by Ctrl-C or SIGTERM (resumable)\n";
    return text;
}

int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err)
{
    if (args.empty())
    {
        err << usage();
        return kExitUsageError;
    }
    const std::string& first = args.front();
    if (first == "--help" || first == "-h" || first == "help")
    {
        const Command* c = args.size() > 1 ? findCommand(args[1]) : nullptr;
        out << (c != nullptr ? helpText(c->page()) : usage());
        return kExitOk;
    }
    if (first == "--man")
    {
        out << manPage(ROSIN_VERSION);
        return kExitOk;
    }
    if (first == "--completion")
    {
        if (args.size() != 2 || args[1] != "bash")
        {
            err << "error: --completion: expected \"bash\"\n";
            return kExitUsageError;
        }
        out << bashCompletion();
        return kExitOk;
    }
    if (first == "--parse-only")
        return parseOnly({args.begin() + 1, args.end()}, out, err);
    if (first == "--version")
    {
        // The vector path the kernels run on: results round differently per path (Resources/docs/tests.md).
        out << "rosin " ROSIN_VERSION "\n"
            << "kernels: " << physics::simdLevelName(physics::simdLevel())
            << " (ROSIN_SIMD chooses a lower one)\n";
        return kExitOk;
    }
    const Command* command = findCommand(first);
    if (command == nullptr)
    {
        err << "error: unknown command \"" << first << "\"\n"
            << "see 'rosin --help'\n";
        return kExitUsageError;
    }
    try
    {
        return command->run(std::vector<std::string>(args.begin() + 1, args.end()), out, err);
    }
    catch (const UsageError& e)
    {
        err << "error: " << e.what() << "\nsee 'rosin " << command->name << " --help'\n";
        return kExitUsageError;
    }
    catch (const std::exception& e)
    {
        err << "error: " << e.what() << "\n";
        return kExitInputError;
    }
    catch (...)
    {
        err << "error: unexpected failure\n";
        return kExitInputError;
    }
}

} // namespace rosin::cli
