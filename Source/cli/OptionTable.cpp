#include "cli/OptionTable.h"

#include <algorithm>

namespace rosin::cli
{

namespace
{
/// "-h, --help" -> {"-h", "--help"}.
std::vector<std::string> namesOf(const std::string& names)
{
    std::vector<std::string> list;
    std::size_t begin = 0;
    while (begin < names.size())
    {
        const std::size_t comma = std::min(names.find(", ", begin), names.size());
        list.push_back(names.substr(begin, comma - begin));
        begin = comma + 2;
    }
    return list;
}
} // namespace

bool ParsedOptions::has(const std::string& name) const
{
    return std::any_of(options_.begin(), options_.end(), [&](const Option& o) { return o.name == name; });
}

const std::string* ParsedOptions::value(const std::string& name) const
{
    const std::string* found = nullptr;
    for (const Option& o : options_)
        if (o.name == name && o.value)
            found = &*o.value;
    return found;
}

std::vector<std::string> ParsedOptions::values(const std::string& name) const
{
    std::vector<std::string> found;
    for (const Option& o : options_)
        if (o.name == name && o.value)
            found.push_back(*o.value);
    return found;
}

double ParsedOptions::number(const std::string& name, const physics::Range& range, double fallback) const
{
    const std::string* text = value(name);
    return text == nullptr ? fallback : parseNumberIn(name, *text, range);
}

OptionTable::OptionTable(std::vector<OptionSpec> rows, int column) : rows_(std::move(rows)), column_(column)
{
}

ParsedOptions OptionTable::parse(const std::vector<std::string>& args) const
{
    std::vector<std::string> withValue, flags;
    for (const OptionSpec& row : rows_)
        for (const std::string& name : namesOf(row.names))
            (row.value.empty() ? flags : withValue).push_back(name);
    std::vector<Option> options = parseOptions(args, withValue, flags);
    for (Option& o : options) // an alias is stored under its row's last name
        for (const OptionSpec& row : rows_)
        {
            const std::vector<std::string> names = namesOf(row.names);
            if (std::find(names.begin(), names.end(), o.name) != names.end())
                o.name = names.back();
        }
    return ParsedOptions(std::move(options));
}

std::string OptionTable::describe() const
{
    std::string text;
    const std::string indent(static_cast<std::size_t>(column_), ' ');
    for (const OptionSpec& row : rows_)
    {
        if (row.names.empty())
        {
            text += row.help + "\n";
            continue;
        }
        std::string line = "  " + row.names + (row.value.empty() ? "" : " " + row.value);
        if (static_cast<int>(line.size()) < column_)
            line += std::string(static_cast<std::size_t>(column_) - line.size(), ' ');
        else
            line += "\n" + indent;
        std::size_t begin = 0;
        for (;;)
        {
            const std::size_t end = row.help.find('\n', begin);
            line += row.help.substr(begin, end == std::string::npos ? std::string::npos : end - begin) + "\n";
            if (end == std::string::npos)
                break;
            line += indent;
            begin = end + 1;
        }
        text += line;
    }
    return text;
}

std::vector<std::string> OptionTable::valueOptions() const
{
    std::vector<std::string> names;
    for (const OptionSpec& row : rows_)
        if (!row.names.empty() && !row.value.empty())
            names.push_back(namesOf(row.names).back());
    return names;
}

double parseNumberIn(const std::string& option, const std::string& text, const physics::Range& range)
{
    const double v = parseNumber(option, text);
    if (!range.contains(v))
        badOptionValue(option, range.describe(), text);
    return v;
}

} // namespace rosin::cli
