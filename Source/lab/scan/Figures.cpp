#include "lab/scan/Figures.h"

#include "lab/scan/ChildProcess.h"
#include "lab/scan/HelperScripts.h"

#ifndef ROSIN_FIGURE_SCRIPT
#define ROSIN_FIGURE_SCRIPT ""
#endif

namespace rosin::scan
{

std::string figureScriptPath()
{
    return findHelperScript("plot_scan.py", "ROSIN_FIGURE_SCRIPT", ROSIN_FIGURE_SCRIPT);
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
    const std::string& python = figurePython();
    if (python.empty())
    {
        err << "warning: figures not drawn: no Python with matplotlib and numpy (tried "
            << figurePythonCandidates()
            << "; Debian: apt-get install python3-matplotlib, or set ROSIN_PYTHON)" << consequence;
        return false;
    }
    std::vector<std::string> argv{python, script};
    std::string shown = python + " " + script;
    for (const auto& a : arguments)
    {
        argv.push_back(a);
        // Appended piecewise: GCC 12 warns (-Wrestrict, a false positive) on " " + std::string here.
        shown.append(" ").append(a);
    }
    const int status = runProgram(argv);
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
