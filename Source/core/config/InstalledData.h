#pragma once
// Where Rosin's installed data (presets, figure scripts, the demo) lies, found from the running executable so
// an installed `rosin` (PREFIX/bin/rosin, data in PREFIX/share/rosin), a per-user install and the build tree
// all work without the source tree:
//   1. EXE_DIR/../share/rosin/SUBFOLDER  (an installed rosin);
//   2. EXE_DIR/share/rosin/SUBFOLDER     (the build tree: build/rosin, data copied there at build time).
#include <string>
#include <vector>

namespace rosin::config
{

/// The folder of the running executable (from /proc/self/exe), or empty if unknown.
std::string executableFolder();

/// The candidate folders for `subfolder` of Rosin's data ("presets", "figures", "demo"), in the order above.
std::vector<std::string> installedDataFolders(const std::string& subfolder);

} // namespace rosin::config
