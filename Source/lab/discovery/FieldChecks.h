#pragma once
// Typed fields of dataset.json: numbers in the ranges the spec states (physics::Range: open ends as in
// "0 < beta < 0.5", no maximum as in "bowForce > 0", integers), strings and arrays.
#include <cstdint>
#include <limits>
#include <optional>
#include <string>

#include "core/config/JsonObject.h"
#include "core/physics/units/Range.h"

namespace rosin::discovery
{

using physics::Range;

/// The member as a number within `range`; throws DatasetError naming the field if absent or out of bounds.
double requiredNumber(const config::JsonObject& object, const std::string& key, const Range& range);
/// As requiredNumber, but an absent member gives std::nullopt.
std::optional<double> optionalNumber(const config::JsonObject& object, const std::string& key,
                                     const Range& range);
/// A required string member (any text, possibly empty).
std::string requiredString(const config::JsonObject& object, const std::string& key);
/// A required array member with at least one element.
const nlohmann::json& requiredArray(const config::JsonObject& object, const std::string& key);
/// "channels" + 2 -> "channels[2]".
std::string elementPath(const std::string& arrayPath, std::size_t index);

/// Temperatures are in degrees Celsius; below absolute zero is a unit slip or a typo.
inline constexpr Range kCelsius{.min = -273.15, .unit = "deg C", .minOpen = true};

} // namespace rosin::discovery
