#pragma once
// Small helpers shared by the subcommands: "--name value" / "--name=value" option parsing and the
// usage-error type (exit status 2; bad values are exit status 1).
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace rosin::cli
{

/// Exit statuses of every subcommand.
enum ExitStatus : int
{
    kExitOk = 0,
    kExitInputError = 1, ///< a bad value, file or preset, or a failed render
    kExitUsageError = 2  ///< unknown command or option, missing option value
};

/// Wrong command-line shape (not a wrong value): the dispatcher prints it with a pointer to --help.
class UsageError : public std::runtime_error
{
  public:
    using std::runtime_error::runtime_error;
};

struct Option
{
    std::string name;                 ///< "--out"
    std::optional<std::string> value; ///< absent for flags
};

/// Splits args into options. Options in `withValue` take one value ("--out x" or "--out=x"); those in `flags`
/// take none. Throws UsageError on anything else (unknown option, positional argument, missing value).
std::vector<Option> parseOptions(const std::vector<std::string>& args,
                                 const std::vector<std::string>& withValue,
                                 const std::vector<std::string>& flags);

/// Parses the whole of `text` as a number; throws ConfigError naming `option` if it is not one.
double parseNumber(const std::string& option, const std::string& text);
/// Throws ConfigError: `option` got `value` where `expected` was.
[[noreturn]] void badOptionValue(const std::string& option, const std::string& expected,
                                 const std::string& value);
/// Throws ConfigError naming `option` unless `value` is one of `allowed`.
void requireChoice(const std::string& option, const std::string& value,
                   const std::vector<std::string>& allowed);

/// `words` joined by single spaces and wrapped at `width` columns: the first line starts with `first`, every
/// further line with `indent` spaces. Ends with a newline.
std::string wrapWords(const std::vector<std::string>& words, const std::string& first, std::size_t indent,
                      std::size_t width);

/// `value` with `digits` significant digits (printf's %g), for messages and reports.
std::string significant(double value, int digits);

/// The peak a listening WAV is scaled to unless --scale says otherwise: -1 dBFS, so it never clips when
/// converted.
inline constexpr double kListeningPeak = 0.8912509381337456;

} // namespace rosin::cli
