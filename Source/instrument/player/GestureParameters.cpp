#include "instrument/player/GestureParameters.h"

#include <algorithm>
#include <cmath>

namespace rosin::player::midimap
{

double controllerFactor(int value) noexcept
{
    return std::exp2((std::clamp(value, 0, 127) - 64) / 32.0);
}

double betaControllerFactor(int value) noexcept
{
    return std::exp2((std::clamp(value, 0, 127) - 64) / 64.0);
}

double accelerationScale(int velocity) noexcept
{
    return 0.25 + 0.75 * std::clamp(velocity, 0, 127) / 127.0;
}

double attackForceScale(int velocity) noexcept
{
    return 0.5 + std::clamp(velocity, 0, 127) / 127.0;
}

} // namespace rosin::player::midimap
