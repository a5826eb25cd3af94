#pragma once
// A command's options declared once: the table says which options exist, which take a value and what each
// means, and from it come both the parsing (what is accepted) and the option lines of --help, so the two
// cannot drift apart. Values are still checked by the command (ParsedOptions::number with a physics::Range
// says what was expected in the same words as every other check).
#include <string>
#include <vector>

#include "cli/CommandLine.h"
#include "core/physics/units/Range.h"

namespace rosin::cli
{

/// One row of a command's table: an option, or a heading between groups of options.
struct OptionSpec
{
    std::string names; ///< "--sample-rate", or with a short alias first "-h, --help"; empty: a heading
    std::string value; ///< the value as help shows it ("HZ", "A:B"); empty: a flag that takes none
    std::string help;  ///< shown beside the name; '\n' starts a continuation line; a heading's own text
};

/// A command's options as typed, checked against its table. Aliases are stored under the option's last
/// (long) name: "-h" is has("--help").
class ParsedOptions
{
  public:
    explicit ParsedOptions(std::vector<Option> options) : options_(std::move(options)) {}
    bool has(const std::string& name) const;
    /// The last value given for `name`, or null.
    const std::string* value(const std::string& name) const;
    /// Every value given for `name`, in order.
    std::vector<std::string> values(const std::string& name) const;
    /// The last value of `name` as a number in `range`, or `fallback` when absent; ConfigError (naming the
    /// option and what was expected) when it is not one.
    double number(const std::string& name, const physics::Range& range, double fallback) const;
    const std::vector<Option>& all() const noexcept { return options_; }

  private:
    std::vector<Option> options_;
};

class OptionTable
{
  public:
    /// `column`: where the help text of every option starts in describe().
    explicit OptionTable(std::vector<OptionSpec> rows, int column = 27);

    /// Parses `args` ("--name value" or "--name=value"; flags take no value). UsageError for an unknown
    /// option, a positional argument, a missing value or a value given to a flag.
    ParsedOptions parse(const std::vector<std::string>& args) const;
    /// The help lines of the table: a heading as it is; an option as "  NAMES VALUE" with its help from
    /// `column` on (on the next line when the name reaches the column), continuation lines indented alike.
    std::string describe() const;
    /// The long names of the options that take a value.
    std::vector<std::string> valueOptions() const;
    /// The rows as declared, for the man page and the shell completion.
    const std::vector<OptionSpec>& rows() const noexcept { return rows_; }

  private:
    std::vector<OptionSpec> rows_;
    int column_;
};

/// A number in `range` from an option's text; ConfigError naming the option and the range otherwise.
double parseNumberIn(const std::string& option, const std::string& text, const physics::Range& range);

} // namespace rosin::cli
