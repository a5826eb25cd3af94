#include "core/config/ConfigError.h"

namespace rosin::config
{

namespace
{
std::string compose(const std::string& file, const std::string& field, const std::string& expected,
                    const std::string& got)
{
    std::string text = file + ": ";
    if (!field.empty())
        text += "field \"" + field + "\": ";
    text += "expected " + expected;
    if (!got.empty())
        text += " but got " + got;
    return text;
}
} // namespace

ConfigError::ConfigError(std::string file, std::string field, std::string expected, std::string got)
    : std::runtime_error(compose(file, field, expected, got)), file_(std::move(file)),
      field_(std::move(field)), expected_(std::move(expected)), got_(std::move(got))
{
}

} // namespace rosin::config
