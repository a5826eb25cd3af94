#include "core/config/JsonFile.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/config/JsonObject.h"

namespace rosin::config
{

nlohmann::json readJsonFile(const std::string& path)
{
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        throw ConfigError(path, "", "an existing file", "no such file");
    if (std::filesystem::is_directory(path, ec))
        throw ConfigError(path, "", "a file", "a directory");
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw ConfigError(path, "", "a readable file", "a file that cannot be opened");
    std::ostringstream text;
    text << in.rdbuf();
    return parseJsonText(text.str(), path);
}

nlohmann::json parseJsonText(const std::string& text, const std::string& path)
{
    try
    {
        return nlohmann::json::parse(text);
    }
    catch (const nlohmann::json::exception& e)
    {
        // A syntax error, or a number beyond double's range (out_of_range.406, found by fuzzing: it escaped
        // as an uncaught exception). Drop nlohmann's "[json.exception.parse_error.101] " prefix; keep "parse
        // error at line L, column C: ..." or "number overflow parsing '1e3080'".
        std::string detail = e.what();
        if (const auto close = detail.find("] ");
            detail.rfind("[json.exception", 0) == 0 && close != std::string::npos)
            detail = detail.substr(close + 2);
        throw ConfigError(path, "", "valid JSON", detail);
    }
}

void requireFormat(const nlohmann::json& root, const std::string& path, const std::string& format)
{
    const JsonObject object(root, path, "");
    const std::string expected = "\"" + format + "\"";
    if (!object.has("format"))
        object.fail("format", expected, "nothing (the field is required)");
    const auto& value = object.at("format");
    if (!value.is_string() || value.get<std::string>() != format)
        object.fail("format", expected, describeJson(value));
}

} // namespace rosin::config
