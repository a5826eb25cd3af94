#pragma once
// The one vocabulary of allowed values: a quantity's range with its unit, used wherever a value is checked
// and an error has to say what was expected (gesture scripts, presets, the command line, datasets, the
// plugin's parameter table). Ends may be open or absent (infinite), a value may have to be an integer or
// non-zero. describe() says it in words for messages: "a number in 0.01..0.5", "a number > 0 and <= 600 (s)",
// "an integer in 8000..384000 (Hz)", "a non-zero number (m/s^2)".
#include <limits>
#include <string>

namespace rosin::physics
{

struct Range
{
    double min = -std::numeric_limits<double>::infinity(); ///< -inf: no lower end
    double max = std::numeric_limits<double>::infinity();  ///< +inf: no upper end
    const char* unit = "";
    bool minOpen = false; ///< (min, ...: min itself excluded
    bool maxOpen = false; ///< ..., max): max itself excluded
    bool integer = false; ///< an integral value (44100 or 44100.0)
    bool nonZero = false;

    /// False for non-finite values.
    bool contains(double value) const noexcept;
    std::string describe() const;
};

/// Shortest round-trip text of a number, for messages ("0.9", "1e-06", "inf", "nan").
std::string formatNumber(double value);

namespace limits
{
/// The sample rates every engine and command takes.
inline constexpr Range sampleRate{8000.0, 384000.0, "Hz", false, false, true};
} // namespace limits

} // namespace rosin::physics
