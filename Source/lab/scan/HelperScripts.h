#pragma once
// Where Rosin's figure scripts are: found relative to the running executable, so an installed or
// copied `rosin` and the build tree both work without the source tree.
//   1. the environment variable that names the script, when set and non-empty;
//   2. EXE_DIR/../share/rosin/figures/NAME (an installed rosin: PREFIX/bin/rosin);
//   3. EXE_DIR/share/rosin/figures/NAME (the build tree: build/rosin, scripts copied at build time)
//      (2 and 3: config/InstalledData.h);
//   4. the source tree this was built from (tests that run in-process from other folders).
#include <string>
#include <vector>

namespace rosin::scan
{

/// The first existing candidate for script `fileName`, or the first candidate when none exists (so the
/// warning names where it was expected). `builtIn` is the source-tree path (may be empty).
std::string findHelperScript(const std::string& fileName, const char* environmentVariable,
                             const std::string& builtIn);
/// Every place findHelperScript looks, in order, for messages.
std::vector<std::string> helperScriptCandidates(const std::string& fileName, const char* environmentVariable,
                                                const std::string& builtIn);

} // namespace rosin::scan
