#include "HelperScripts.h"

#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace rosin::scan
{

namespace fs = std::filesystem;

namespace
{
fs::path executableFolder()
{
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    return ec ? fs::path() : exe.parent_path();
}
} // namespace

std::vector<std::string> helperScriptCandidates(const std::string& fileName, const char* environmentVariable,
                                                const std::string& builtIn)
{
    const char* overridden = std::getenv(environmentVariable);
    if (overridden != nullptr && *overridden != '\0')
        return {overridden}; // named explicitly: nothing else is tried
    std::vector<std::string> candidates;
    if (const fs::path exe = executableFolder(); !exe.empty())
    {
        candidates.push_back((exe.parent_path() / "share" / "rosin" / "figures" / fileName).string());
        candidates.push_back((exe / "share" / "rosin" / "figures" / fileName).string());
    }
    if (!builtIn.empty())
        candidates.push_back(builtIn);
    return candidates;
}

std::string findHelperScript(const std::string& fileName, const char* environmentVariable,
                             const std::string& builtIn)
{
    const auto candidates = helperScriptCandidates(fileName, environmentVariable, builtIn);
    std::error_code ec;
    for (const auto& candidate : candidates)
        if (fs::is_regular_file(candidate, ec))
            return candidate;
    return candidates.empty() ? std::string() : candidates.front();
}

} // namespace rosin::scan
