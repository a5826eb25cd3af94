#pragma once
// The PNG figures of a finished scan, drawn by the Python script Source/lab/figures/plot_scan.py (run as
// `python3 SCRIPT DIR` after scan.csv and scan.json are written). Figures are optional: when python3, the
// script or its libraries are missing, a warning names what is missing and the scan's files stay as they are.
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace rosin::scan
{

/// $ROSIN_FIGURE_SCRIPT if set and non-empty, else the script of the source tree this was built from.
std::string figureScriptPath();
/// Runs the script on `dir`. Returns true if it succeeded; otherwise writes a warning to `err`.
bool drawFigures(const std::filesystem::path& dir, std::ostream& err);
/// Runs `python3 SCRIPT arguments...` (the script's other modes: compare, loop). Returns true if it
/// succeeded; otherwise writes a warning naming what is missing to `err`, ending with `consequence`.
bool runFigureScript(const std::vector<std::string>& arguments, std::ostream& err,
                     const std::string& consequence);

} // namespace rosin::scan
