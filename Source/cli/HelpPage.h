#pragma once
// One command's manual, written once: `rosin COMMAND --help` prints it as text and `rosin --man` sets it as
// that command's section of the man page, with the options of the very tables the command parses with, so
// help, man page and bash completion cannot drift apart.
#include <string>
#include <vector>

#include "cli/OptionTable.h"

namespace rosin::cli
{

/// Prose (paragraphs split by blank lines; lines that start with two spaces are kept as they are: lists,
/// columns) or an option table, under an optional heading ("options", "effects").
struct HelpSection
{
    std::string heading;
    std::string prose;
    const OptionTable* options = nullptr;
};

struct HelpPage
{
    std::string command;                  ///< "render", "scan", ...
    std::vector<std::string> usage;       ///< one command form per entry, unwrapped ("rosin scan merge DIR")
    std::vector<HelpSection> sections;    ///< in order
    std::vector<std::string> examples;    ///< whole command lines; a trailing " \\\n" continues one
    std::string exitStatus;               ///< "0 success, 1 bad value, ..."
    std::vector<std::string> subcommands; ///< words that may follow the command ("schelleng", "merge")
};

/// The page as `--help` prints it: usage forms wrapped at 110 columns, sections, examples, exit status.
std::string helpText(const HelpPage& page);

/// The page as a man(7) section: .SS per form, prose as filled text, option tables as .TP items.
std::string helpRoff(const HelpPage& page);

/// `text` with roff's special characters escaped (backslash, a leading dot or quote, hyphens as \-).
std::string roffEscape(const std::string& text);

} // namespace rosin::cli
