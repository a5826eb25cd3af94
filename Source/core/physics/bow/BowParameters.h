#pragma once
// The bow as the string feels it: the width of the hair ribbon that touches the string and the hair's own
// give in the bowing direction (Resources/docs/physics.md, "The bow's width and hair"). The defaults, zero
// width and rigid hair, are the point contact of the seeds, whose experiments bowed with a rod
// ([Galluzzo2017] section 2: "rods rather than normal bows").
#include <string>

#include "core/physics/units/Range.h"

namespace rosin::physics
{

namespace limits
{
/// What a bow may be, wherever it is given (a preset, a scan option, a VoiceConfig).
inline constexpr Range bowWidth{0.0, 0.03, "m"};
inline constexpr Range hairStiffness{1e2, 1e8, "N/m"};
inline constexpr Range hairDamping{0.1, 1e4, "kg/s"};
inline constexpr Range slipNoise{0.0, 0.5, "(relative rms)"};
} // namespace limits

struct BowParameters
{
    /// Contact width of the ribbon along the string, m (0: a point). The friction force is spread evenly over
    /// it and the ribbon sticks or slips as a whole.
    double width = 0.0;
    /// The hair yields in the bowing direction as a spring and dashpot in parallel (Kelvin-Voigt, the form of
    /// Pitteroff and Woodhouse's hair model); false: rigid hair.
    bool compliantHair = false;
    double hairStiffness = 0.0; ///< k_h, N/m: the ribbon's stretch towards frog and tip
    double hairDamping = 0.0;   ///< r_h, kg/s: the ribbon's longitudinal wave impedance, both ways
    /// Relative rms fluctuation of the force the ribbon slides with (SlipNoise.h); 0: the seeds' smooth rod.
    double slipNoise = 0.0;
};

/// The slip noise of a ribbon whose hairs on the string catch and release independently, each by as much
/// as its own share of the force: 1 / sqrt(hairs on the string) (BowParameters.cpp gives the count).
double ribbonSlipNoise();

/// A cellist's bow at mid-bow from horsehair's handbook constants (BowParameters.cpp gives the numbers and
/// their sources): `width` m of ribbon on the string, compliant hair.
BowParameters horsehairBow(double width);

/// Throws std::invalid_argument naming `where` and the field when a value is outside its range.
void validateBow(const BowParameters& bow, const std::string& where);

} // namespace rosin::physics
