#pragma once
// What the command-line tests share: the outcome of running `rosin`, shell quoting and reading files back.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <vector>

namespace rosin::test::cli
{

/// Exit status and the captured standard output and error of one run.
struct Result
{
    int status = -1;
    std::string out, err;
};

/// Single-quotes `arg` for /bin/sh, so paths and values with spaces or quotes pass through unchanged.
inline std::string quote(const std::string& arg)
{
    std::string q = "'";
    for (char c : arg)
        q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

/// The whole file, bytes as they are ("" if it cannot be read).
inline std::string slurp(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

#if defined(ROSIN_BINARY) && defined(ROSIN_SOURCE_PRESET_DIR)
/// Runs the built `rosin` with `args` in `workDir` (factory presets from the source tree), capturing its
/// output in workDir/stdout.txt and workDir/stderr.txt. `environment`: more NAME=VALUE settings for the run.
inline Result runRosin(const std::string& workDir, const std::vector<std::string>& args,
                       const std::string& environment = "")
{
    std::string command = "cd " + quote(workDir) + " && ROSIN_PRESET_DIR=" + quote(ROSIN_SOURCE_PRESET_DIR) +
                          " " + environment + " " + quote(ROSIN_BINARY);
    for (const auto& a : args)
        command += " " + quote(a);
    const std::string out = workDir + "/stdout.txt", err = workDir + "/stderr.txt";
    const int raw = std::system((command + " >" + quote(out) + " 2>" + quote(err)).c_str());
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(out), slurp(err)};
}
#endif

} // namespace rosin::test::cli
