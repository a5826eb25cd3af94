#include "lab/scan/HelperScripts.h"

#include <cstdlib>
#include <filesystem>
#include <system_error>

#include "core/config/InstalledData.h"

namespace rosin::scan
{

namespace fs = std::filesystem;

std::vector<std::string> helperScriptCandidates(const std::string& fileName, const char* environmentVariable,
                                                const std::string& builtIn)
{
    const char* overridden = std::getenv(environmentVariable);
    if (overridden != nullptr && *overridden != '\0')
        return {overridden}; // named explicitly: nothing else is tried
    std::vector<std::string> candidates;
    for (const auto& folder : config::installedDataFolders("figures"))
        candidates.push_back((fs::path(folder) / fileName).string());
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
