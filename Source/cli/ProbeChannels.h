#pragma once
// The internal channels `rosin render --probe` writes, in file order. Names and units follow the
// measured-data format (Resources/docs/measurements.md), so a probe file can stand in for a measured trial.
#include <array>

namespace rosin::cli
{

struct ProbeChannel
{
    const char* name;
    const char* unit;
    const char* what;
};

inline constexpr std::array<ProbeChannel, 5> kProbeChannels = {{
    {"bridgeForce", "N", "transverse force of the string on the bridge"},
    {"bowPointVelocity", "m/s", "string velocity at the bowed point"},
    {"frictionForce", "N", "friction force of the bow on the string"},
    {"bowVelocity", "m/s", "bow velocity"},
    {"contactTemperature", "K", "contact temperature above ambient (0 for curve laws)"},
}};

} // namespace rosin::cli
