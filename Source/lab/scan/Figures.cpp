#include "Figures.h"

#include <cstdlib>
#include <sys/wait.h>

#ifndef ROSIN_FIGURE_SCRIPT
#define ROSIN_FIGURE_SCRIPT ""
#endif

namespace rosin::scan
{

namespace
{
std::string quoted(const std::string& text)
{
    std::string q = "'";
    for (const char c : text)
        q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

int shellStatus(const std::string& command)
{
    const int raw = std::system(command.c_str());
    return raw != -1 && WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}
} // namespace

std::string figureScriptPath()
{
    const char* overridden = std::getenv("ROSIN_FIGURE_SCRIPT");
    return overridden != nullptr && *overridden != '\0' ? overridden : ROSIN_FIGURE_SCRIPT;
}

bool runFigureScript(const std::vector<std::string>& arguments, std::ostream& err,
                     const std::string& consequence)
{
    const std::string script = figureScriptPath();
    std::error_code ec;
    if (script.empty() || !std::filesystem::is_regular_file(script, ec))
    {
        err << "warning: figures not drawn: the figure script "
            << (script.empty() ? "(none built in)" : script) << " is missing" << consequence;
        return false;
    }
    if (shellStatus("command -v python3 >/dev/null 2>&1") != 0)
    {
        err << "warning: figures not drawn: python3 is not installed (with matplotlib and numpy)"
            << consequence;
        return false;
    }
    std::string command = "python3 " + quoted(script), shown = "python3 " + script;
    for (const auto& a : arguments)
    {
        // Appended piecewise: GCC 12 warns (-Wrestrict, a false positive) on " " + std::string here.
        command.append(" ").append(quoted(a));
        shown.append(" ").append(a);
    }
    const int status = shellStatus(command);
    if (status != 0)
    {
        err << "warning: figures not drawn: " << shown << " exited with status " << status
            << " (are matplotlib and numpy installed?)" << consequence;
        return false;
    }
    return true;
}

bool drawFigures(const std::filesystem::path& dir, std::ostream& err)
{
    return runFigureScript({dir.string()}, err,
                           "; scan.csv and scan.json are complete (use --no-figures to skip figures)\n");
}

} // namespace rosin::scan
