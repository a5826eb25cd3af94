#pragma once
// The subcommands of `rosin`, declared once: the dispatcher runs them, the man page and the shell completion
// are generated from their manuals (HelpPage), and --parse-only checks a command line against their parsers.
#include <ostream>
#include <string>
#include <vector>

#include "cli/HelpPage.h"

namespace rosin::cli
{

struct Command
{
    const char* name;
    const char* summary;
    int (*run)(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
    HelpPage (*page)();
    /// Parses the arguments as run() would, without running; throws UsageError or ConfigError.
    void (*check)(const std::vector<std::string>& args);
};

const std::vector<Command>& commands();
/// The command of that name, or null.
const Command* findCommand(const std::string& name);

} // namespace rosin::cli
