#pragma once
// Typed, validating access to one JSON object of a config file. Every failure throws ConfigError with the
// file, the full path of the field ("contact.radius") and what was expected.
#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/config/ConfigError.h"
#include "core/physics/units/Range.h"

namespace rosin::config
{

/// Short description of a JSON value for "but got ...": "\"plasticc\"", "0.9", "an object", "null".
std::string describeJson(const nlohmann::json& value);

class JsonObject
{
  public:
    /// Throws ConfigError unless `value` is an object. `path` is its own field path ("" for the root).
    JsonObject(const nlohmann::json& value, std::string file, std::string path);

    bool has(const std::string& key) const { return value_.contains(key); }
    const nlohmann::json& at(const std::string& key) const { return value_.at(key); }
    /// The full path of a member, e.g. "contact" + "radius" -> "contact.radius".
    std::string path(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
    const std::string& file() const { return file_; }

    double number(const std::string& key, const physics::Range& range) const;
    std::optional<double> optionalNumber(const std::string& key, const physics::Range& range) const;
    std::optional<bool> optionalBool(const std::string& key) const;
    std::optional<std::string> optionalString(const std::string& key) const;
    /// A string that must be one of `allowed`; absent gives std::nullopt.
    std::optional<std::string> optionalOneOf(const std::string& key,
                                             const std::vector<std::string>& allowed) const;
    /// The member as an object (throws if absent or not an object).
    JsonObject object(const std::string& key) const;
    /// Rejects members not in `known` (catches typos such as "frcition").
    void allowOnly(std::initializer_list<const char*> known) const;

    [[noreturn]] void fail(const std::string& key, const std::string& expected, const std::string& got) const;

  private:
    const nlohmann::json& value_;
    std::string file_;
    std::string path_;
};

/// "one of a, b, c".
std::string oneOfText(const std::vector<std::string>& allowed);

} // namespace rosin::config
