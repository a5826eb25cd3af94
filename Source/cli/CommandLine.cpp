#include "cli/CommandLine.h"

#include <cstdio>

#include <algorithm>
#include <charconv>

#include "core/config/ConfigError.h"
#include "core/config/JsonObject.h"

namespace rosin::cli
{

namespace
{
bool contains(const std::vector<std::string>& list, const std::string& value)
{
    return std::find(list.begin(), list.end(), value) != list.end();
}
} // namespace

std::vector<Option> parseOptions(const std::vector<std::string>& args,
                                 const std::vector<std::string>& withValue,
                                 const std::vector<std::string>& flags)
{
    std::vector<Option> options;
    for (std::size_t i = 0; i < args.size(); ++i)
    {
        const std::string& arg = args[i];
        if (arg.rfind("-", 0) != 0)
            throw UsageError("unexpected argument \"" + arg + "\"");
        const auto eq = arg.find('=');
        Option option{arg.substr(0, eq), std::nullopt};
        if (eq != std::string::npos)
            option.value = arg.substr(eq + 1);

        if (contains(flags, option.name))
        {
            if (option.value)
                throw UsageError(option.name + " takes no value");
        }
        else if (contains(withValue, option.name))
        {
            if (!option.value)
            {
                if (i + 1 >= args.size())
                    throw UsageError(option.name + " needs a value");
                option.value = args[++i];
            }
        }
        else
        {
            throw UsageError("unknown option \"" + option.name + "\"");
        }
        options.push_back(std::move(option));
    }
    return options;
}

double parseNumber(const std::string& option, const std::string& text)
{
    double value = 0.0;
    const char* last = text.data() + text.size();
    const auto result = std::from_chars(text.data(), last, value);
    if (text.empty() || result.ec != std::errc() || result.ptr != last)
        throw config::ConfigError(option, "", "a number", "\"" + text + "\"");
    return value;
}

[[noreturn]] void badOptionValue(const std::string& option, const std::string& expected,
                                 const std::string& value)
{
    throw config::ConfigError(option, "", expected, "\"" + value + "\"");
}

void requireChoice(const std::string& option, const std::string& value,
                   const std::vector<std::string>& allowed)
{
    if (std::find(allowed.begin(), allowed.end(), value) == allowed.end())
        badOptionValue(option, config::oneOfText(allowed), value);
}

std::string wrapWords(const std::vector<std::string>& words, const std::string& first, std::size_t indent,
                      std::size_t width)
{
    std::string result, line = first;
    bool lineEmpty = true;
    for (const std::string& word : words)
    {
        if (!lineEmpty && line.size() + 1 + word.size() > width)
        {
            result += line + "\n";
            line.assign(indent, ' ');
            lineEmpty = true;
        }
        line += (lineEmpty ? "" : " ") + word;
        lineEmpty = false;
    }
    return result + line + "\n";
}

std::string significant(double value, int digits)
{
    char buffer[64];
    std::snprintf(buffer, sizeof(buffer), "%.*g", digits, value);
    return buffer;
}

} // namespace rosin::cli
