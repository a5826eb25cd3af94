#include "cli/Dispatcher.h"

#include <cstdio>
#include <exception>

#include "cli/CommandLine.h"
#include "cli/DiscoverCommand.h"
#include "cli/RenderCommand.h"
#include "cli/ScanCommand.h"
#include "cli/SynthDataCommand.h"
#include "core/physics/modal/SimdLevel.h"

#ifndef ROSIN_VERSION
#define ROSIN_VERSION "unknown"
#endif

namespace rosin::cli
{

namespace
{
struct Command
{
    const char* name;
    const char* summary;
    int (*run)(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
    std::string (*help)();
};

// One entry (and one file) per subcommand.
const Command kCommands[] = {
    {"render", "render a bow gesture to a WAV of the bridge force (and a probe of internal channels)",
     runRender, renderHelp},
    {"scan", "Schelleng and Guettler playability diagrams over a grid of bowings (all cores, resumable)",
     runScan, scanHelp},
    {"synth-data",
     "a measured-like dataset from the model with physical effects hidden (discovery test data)",
     runSynthData, synthDataHelp},
    {"discover", "where a measured dataset and the model disagree, and which physical effect is missing",
     runDiscover, discoverHelp},
};

const Command* findCommand(const std::string& name)
{
    for (const auto& c : kCommands)
        if (name == c.name)
            return &c;
    return nullptr;
}
} // namespace

std::string usage()
{
    std::string text = "rosin " ROSIN_VERSION " - physically modelled bowed string\n"
                       "\n"
                       "usage: rosin COMMAND [options]\n"
                       "       rosin COMMAND --help     options of one command\n"
                       "       rosin --help | --version\n"
                       "\n"
                       "commands:\n";
    for (const auto& c : kCommands)
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
        out << (c != nullptr ? c->help() : usage());
        return kExitOk;
    }
    if (first == "--version")
    {
        // The vector path the kernels run on: results round differently per path (README "Tests").
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
