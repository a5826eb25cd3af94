#pragma once
// Typed fields of dataset.json: numbers with the bounds the spec states, strings and arrays.
// config::JsonObject's Range has a finite, closed maximum; the spec needs open ends ("0 < beta < 0.5"), no
// maximum ("bowForce > 0") and integers.
#include <cstdint>
#include <limits>
#include <optional>
#include <string>

#include "config/JsonObject.h"

namespace rosin::discovery
{

struct Bounds
{
    double min = -std::numeric_limits<double>::infinity();
    bool minOpen = false;
    double max = std::numeric_limits<double>::infinity();
    bool maxOpen = false;
    const char* unit = "";
    bool integer = false; ///< an integral value (44100 or 44100.0: JSON has one number type)
    bool nonZero = false;

    bool contains(double value) const;
    /// "a number > 0 (N)", "a number > 0 and < 0.5", "an integer in 1000..384000".
    std::string describe() const;
};

/// The member as a number within `bounds`; throws DatasetError naming the field if absent or out of bounds.
double requiredNumber(const config::JsonObject& object, const std::string& key, const Bounds& bounds);
/// As requiredNumber, but an absent member gives std::nullopt.
std::optional<double> optionalNumber(const config::JsonObject& object, const std::string& key,
                                     const Bounds& bounds);
/// A required string member (any text, possibly empty).
std::string requiredString(const config::JsonObject& object, const std::string& key);
/// A required array member with at least one element.
const nlohmann::json& requiredArray(const config::JsonObject& object, const std::string& key);
/// "channels" + 2 -> "channels[2]".
std::string elementPath(const std::string& arrayPath, std::size_t index);

/// Temperatures are in degrees Celsius; below absolute zero is a unit slip or a typo.
inline constexpr Bounds kCelsius{.min = -273.15, .minOpen = true, .unit = "deg C"};

} // namespace rosin::discovery
