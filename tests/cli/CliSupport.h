#pragma once
// What the command-line tests share: the outcome of running `rosin`, shell quoting and reading files back.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

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

} // namespace rosin::test::cli
