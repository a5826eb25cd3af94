#pragma once
// The one error type of the preset and gesture-script readers. It names the file, the field (a JSON path such
// as "contact.radius" or "segments[1].force.to") and what was expected, so a user can fix the file without
// reading the source:
//     presets/foo.json: field "friction": expected one of classical, ... but got "plasticc"
#include <stdexcept>
#include <string>

namespace rosin::config
{

class ConfigError : public std::runtime_error
{
  public:
    /// `field` may be empty for errors about the whole file (not found, not JSON); `got` may be empty.
    ConfigError(std::string file, std::string field, std::string expected, std::string got = {});

    const std::string& file() const noexcept { return file_; }
    const std::string& field() const noexcept { return field_; }
    const std::string& expected() const noexcept { return expected_; }
    const std::string& got() const noexcept { return got_; }

  private:
    std::string file_, field_, expected_, got_;
};

} // namespace rosin::config
