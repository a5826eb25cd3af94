#include "lab/discovery/TrialPath.h"

#include <algorithm>

#include "lab/discovery/Dataset.h"

namespace rosin::discovery
{

namespace fs = std::filesystem;

namespace
{
// Component-wise prefix test: "/data/set" is not inside "/data/s".
bool isInside(const fs::path& folder, const fs::path& candidate)
{
    auto f = folder.begin(), c = candidate.begin();
    for (; f != folder.end(); ++f, ++c)
    {
        if (f->empty()) // a trailing separator gives an empty last component
            continue;
        if (c == candidate.end() || *f != *c)
            return false;
    }
    return c != candidate.end();
}

// base / relative with every symbolic link on the way resolved, dangling ones included: weakly_canonical
// alone stops at the first component that does not exist, and a dangling link there would let a writer
// create a file outside the folder.
fs::path followLinks(const fs::path& base, const fs::path& relative, std::error_code& ec)
{
    fs::path path = base;
    for (const auto& part : relative)
    {
        path /= part;
        for (int hops = 0; fs::is_symlink(fs::symlink_status(path, ec)); ++hops)
        {
            if (hops == 40) // as the kernel's ELOOP limit
            {
                ec = std::make_error_code(std::errc::too_many_symbolic_link_levels);
                return {};
            }
            const fs::path target = fs::read_symlink(path, ec);
            if (ec)
                return {};
            path = fs::weakly_canonical(path.parent_path() / target, ec);
            if (ec)
                return {};
        }
        ec.clear(); // symlink_status of a missing path sets ec; a missing file is fine
    }
    return path;
}
} // namespace

std::optional<std::string> trialFileProblem(const fs::path& folder, const std::string& file)
{
    if (file.empty())
        return "an empty path";
    const fs::path relative(file);
    if (relative.is_absolute() || relative.has_root_path())
        return "an absolute path";
    const fs::path normal = relative.lexically_normal();
    if (normal.empty() || normal == "." || *normal.begin() == "..")
        return "a path that leaves the dataset folder";
    if (!normal.has_filename())
        return "a folder, not a file";
    std::error_code ec;
    const fs::path base = fs::weakly_canonical(fs::absolute(folder), ec);
    if (ec)
        return "a path that cannot be resolved (" + ec.message() + ")";
    const fs::path resolved = followLinks(base, normal, ec);
    if (ec)
        return "a path that cannot be resolved (" + ec.message() + ")";
    if (!isInside(base, resolved))
        return "a path that leads out of the dataset folder through a symbolic link (to " +
               resolved.string() + ")";
    return std::nullopt;
}

fs::path trialFilePath(const Dataset& dataset, const Trial& trial)
{
    if (const auto problem = trialFileProblem(dataset.folder, trial.file))
    {
        const auto index = dataset.trialIndex(trial.id);
        const std::string field = index ? "trials[" + std::to_string(*index) + "].file" : "trials[].file";
        throw DatasetError(dataset.descriptionPath(), field,
                           "a path relative to the dataset folder, inside it",
                           nlohmann::json(trial.file).dump() + ", " + *problem);
    }
    return fs::path(dataset.folder) / fs::path(trial.file).lexically_normal();
}

} // namespace rosin::discovery
