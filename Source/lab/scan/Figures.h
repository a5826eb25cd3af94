#pragma once
// The PNG figures of a finished scan, drawn by the Python script plot_scan.py (Source/lab/figures; found as
// HelperScripts.h says; run as `python3 SCRIPT DIR` after scan.csv and scan.json are written). Figures are
// optional: when python3, the script or its libraries are missing, a warning names what is missing and the
// scan's files stay as they are.
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace rosin::scan
{

/// plot_scan.py, found as HelperScripts.h says ($ROSIN_FIGURE_SCRIPT overrides).
std::string figureScriptPath();
/// Runs the script on `dir`. Returns true if it succeeded; otherwise writes a warning to `err`.
bool drawFigures(const std::filesystem::path& dir, std::ostream& err);
/// Runs `python3 SCRIPT arguments...` (the script's other modes: compare, loop). Returns true if it
/// succeeded; otherwise writes a warning naming what is missing to `err`, ending with `consequence`.
bool runFigureScript(const std::vector<std::string>& arguments, std::ostream& err,
                     const std::string& consequence);

} // namespace rosin::scan
