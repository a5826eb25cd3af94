#pragma once
// Files that are replaced whole or not at all: the text goes to a temporary file in the same folder, which is
// then renamed over the target (atomic on POSIX). A reader, or a process killed mid-write, sees the old file
// or the new one, never a part of it.
#include <filesystem>
#include <string>

namespace rosin::config
{

/// Replaces `file` by `text`. Throws ConfigError(file, "", "a writable file", reason) on failure, leaving the
/// old file as it was and no temporary file behind.
void writeFileAtomically(const std::filesystem::path& file, const std::string& text);

} // namespace rosin::config
