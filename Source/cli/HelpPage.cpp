#include "cli/HelpPage.h"

#include <sstream>

#include "cli/CommandLine.h"

namespace rosin::cli
{

namespace
{
constexpr std::size_t kWidth = 110;

std::vector<std::string> lines(const std::string& text)
{
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        out.push_back(line);
    return out;
}

/// The words of a usage form, a bracketed group ("[--out FILE.wav]") kept as one word.
std::vector<std::string> usageWords(const std::string& form)
{
    std::vector<std::string> words;
    std::string word;
    int depth = 0;
    for (char c : form)
    {
        depth += c == '[' ? 1 : c == ']' ? -1 : 0;
        if (c == ' ' && depth == 0)
        {
            if (!word.empty())
                words.push_back(word);
            word.clear();
        }
        else
            word += c;
    }
    if (!word.empty())
        words.push_back(word);
    return words;
}

/// A usage form wrapped at kWidth, continuation lines under the first argument.
std::string wrapUsage(const std::string& prefix, const std::string& form, const std::string& command)
{
    const std::size_t indent = prefix.size() + std::string("rosin ").size() + command.size() + 1;
    return wrapWords(usageWords(form), prefix, indent, kWidth);
}

bool kept(const std::string& line)
{
    return line.rfind("  ", 0) == 0;
}

/// Prose as roff: a paragraph per blank-line-separated block, filled; a line that starts with two spaces
/// (a list or a column) on a line of its own, its indent kept.
std::string proseRoff(const std::string& prose)
{
    std::string out;
    bool inParagraph = false, lastKept = false;
    for (const std::string& line : lines(prose))
    {
        if (line.empty())
        {
            inParagraph = false;
            continue;
        }
        out += inParagraph ? (kept(line) || lastKept ? ".br\n" : "") : ".PP\n";
        inParagraph = true;
        lastKept = kept(line);
        out += roffEscape(line) + "\n";
    }
    return out;
}

/// An option's help as roff: its lines as written (they were laid out for the help's column).
std::string optionHelpRoff(const std::string& help)
{
    std::string out;
    bool first = true;
    for (const std::string& line : lines(help))
    {
        out += (first ? "" : ".br\n") + roffEscape(line) + "\n";
        first = false;
    }
    return out;
}

std::string tableRoff(const OptionTable& table)
{
    std::string out;
    for (const OptionSpec& row : table.rows())
    {
        if (row.names.empty())
        {
            out += ".PP\n\\fI" + roffEscape(row.help) + "\\fR\n";
            continue;
        }
        out += ".TP\n\\fB" + roffEscape(row.names) + "\\fR";
        if (!row.value.empty())
            out += " \\fI" + roffEscape(row.value) + "\\fR";
        out += "\n" + optionHelpRoff(row.help);
    }
    return out;
}

/// A usage form as roff: the command in bold, a bracketed group held together by unbreakable spaces.
std::string usageRoff(const std::string& form, const std::string& command)
{
    const std::string head = "rosin " + command;
    std::string rest = form.substr(std::min(form.size(), head.size()));
    std::string escaped;
    int depth = 0;
    for (char c : roffEscape(rest))
    {
        depth += c == '[' ? 1 : c == ']' ? -1 : 0;
        escaped += c == ' ' && depth > 0 ? std::string("\\ ") : std::string(1, c);
    }
    return "\\fB" + roffEscape(head) + "\\fR" + escaped + "\n";
}
} // namespace

std::string roffEscape(const std::string& text)
{
    std::string out;
    for (char c : text)
        out += c == '\\' ? std::string("\\e") : c == '-' ? std::string("\\-") : std::string(1, c);
    if (!out.empty() && (out.front() == '.' || out.front() == '\''))
        out.insert(0, "\\&");
    return out;
}

std::string helpText(const HelpPage& page)
{
    std::string text;
    for (std::size_t i = 0; i < page.usage.size(); ++i)
        text += wrapUsage(i == 0 ? "usage: " : "       ", page.usage[i], page.command);
    for (const HelpSection& s : page.sections)
    {
        text += "\n";
        if (!s.heading.empty())
            text += s.heading + ":\n";
        text += s.prose;
        if (!s.prose.empty() && s.prose.back() != '\n')
            text += "\n";
        if (s.options != nullptr)
            text += s.options->describe();
    }
    if (!page.examples.empty())
    {
        text += "\nexamples:\n";
        for (const std::string& e : page.examples)
            text += "  " + e + "\n";
    }
    if (!page.exitStatus.empty())
        text += "\nexit status: " + page.exitStatus + "\n";
    return text;
}

std::string helpRoff(const HelpPage& page)
{
    std::string out = ".SS \"rosin " + page.command + "\"\n";
    for (std::size_t i = 0; i < page.usage.size(); ++i)
        out += (i == 0 ? ".PP\n" : ".br\n") + usageRoff(page.usage[i], page.command);
    for (const HelpSection& s : page.sections)
    {
        if (!s.heading.empty())
            out += ".PP\n\\fB" + roffEscape(s.heading) + "\\fR\n";
        out += proseRoff(s.prose);
        if (s.options != nullptr)
            out += tableRoff(*s.options);
    }
    if (!page.examples.empty())
    {
        out += ".PP\n\\fBexamples\\fR\n.RS\n.nf\n";
        for (const std::string& e : page.examples)
            for (const std::string& line : lines(e))
                out += roffEscape(line) + "\n";
        out += ".fi\n.RE\n";
    }
    if (!page.exitStatus.empty())
        out += ".PP\nExit status: " + roffEscape(page.exitStatus) + "\n";
    return out;
}

} // namespace rosin::cli
