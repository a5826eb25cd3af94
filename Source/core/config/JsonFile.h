#pragma once
// Reading a JSON file with errors that name the file: missing, unreadable, or not valid JSON.
#include <string>

#include <nlohmann/json.hpp>

namespace rosin::config
{

/// Throws ConfigError(path, "", ...) if the file cannot be read or is not valid JSON (with line and column).
nlohmann::json readJsonFile(const std::string& path);
/// Parses text read from `path` (the same messages as readJsonFile; used by the fuzz targets on raw bytes).
nlohmann::json parseJsonText(const std::string& text, const std::string& path);
/// Checks the root's "format" member is exactly `format` (e.g. "rosin-preset/1").
void requireFormat(const nlohmann::json& root, const std::string& path, const std::string& format);

} // namespace rosin::config
