#pragma once
// Valid ranges of the gesture quantities (physics::Range), and the error that names the offending field.
// One table so the built-in specs, gesture scripts and the command line reject the same values.
#include <stdexcept>
#include <string>

#include "core/gesture/GestureScript.h"
#include "core/physics/units/Range.h"

namespace rosin::gesture
{

/// The quantities' one vocabulary of ranges (physics/units/Range.h).
using physics::formatNumber;
using physics::Range;

namespace limits
{
inline constexpr Range beta{0.01, 0.5, ""};
inline constexpr Range force{0.0, 20.0, "N"};
inline constexpr Range speed{-5.0, 5.0, "m/s"};
inline constexpr Range acceleration{-50.0, 50.0, "m/s^2"};
inline constexpr Range finger{0.1, 1.0, ""};
inline constexpr Range seconds{0.0, 600.0, "s", true};
/// The whole gesture, so a render's memory stays bounded.
inline constexpr Range totalSeconds{0.0, 600.0, "s", true};
// The musical mapping's settings (player::GestureParameters; presets' "player" object).
inline constexpr Range dynamics{0.0, 1.0, ""};
inline constexpr Range bowPressure{0.0, 1.0, ""};
inline constexpr Range vibratoDepth{0.0, 40.0, "cents"};
inline constexpr Range vibratoRate{3.0, 9.0, "Hz"};
inline constexpr Range vibratoDelay{0.0, 1.5, "s"};
inline constexpr Range slideTime{0.02, 0.5, "s"};
inline constexpr Range tremoloRate{4.0, 20.0, "Hz"};
} // namespace limits

/// A gesture value outside its range or of the wrong form. `field` is a path such as "beta" or
/// "segments[1].force.to"; front ends prefix the file or spec the gesture came from.
class GestureError : public std::invalid_argument
{
  public:
    GestureError(std::string field, std::string expected, std::string got);
    const std::string& field() const noexcept { return field_; }
    const std::string& expected() const noexcept { return expected_; }
    const std::string& got() const noexcept { return got_; }

  private:
    std::string field_, expected_, got_;
};

/// Throws GestureError(field, range.describe(), value) unless value is finite and in range.
void requireInRange(const std::string& field, double value, const Range& range);
/// Checks every segment's values and the bow speed that acceleration segments reach, starting from `start`.
/// Throws GestureError naming the first offending field ("segments[i].name[.from|.to]").
void validateScript(const GestureScript& script, const GestureStart& start);

} // namespace rosin::gesture
