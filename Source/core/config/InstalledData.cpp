#include "core/config/InstalledData.h"

#include <filesystem>
#include <system_error>

namespace rosin::config
{

namespace fs = std::filesystem;

std::string executableFolder()
{
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    return ec ? std::string() : exe.parent_path().string();
}

std::vector<std::string> installedDataFolders(const std::string& subfolder)
{
    const fs::path exe = executableFolder();
    if (exe.empty())
        return {};
    return {(exe.parent_path() / "share" / "rosin" / subfolder).string(),
            (exe / "share" / "rosin" / subfolder).string()};
}

} // namespace rosin::config
