#include "cli/ListeningOutput.h"

#include <numbers>

#include "core/config/ConfigError.h"
#include "core/physics/body/BodyParameters.h"
#include "core/physics/body/RadiationGains.h"
#include "core/physics/voice/VoiceConfig.h"

namespace rosin::cli
{

const std::vector<std::string>& outputQuantityNames()
{
    static const std::vector<std::string> names = {"radiated", "force", "velocity"};
    return names;
}

OutputQuantity outputQuantityFromName(const std::string& name)
{
    const auto& names = outputQuantityNames();
    for (std::size_t i = 0; i < names.size(); ++i)
        if (name == names[i])
            return static_cast<OutputQuantity>(i);
    throw config::ConfigError("--output", "", "radiated, force or velocity", "\"" + name + "\"");
}

namespace
{
std::string listeningBodyName(const config::Preset& preset)
{
    if (preset.body != "rigid")
        return preset.body;
    return preset.string.name.rfind("violin", 0) == 0 ? "violin" : "cello";
}
} // namespace

ListeningOutput::ListeningOutput(OutputQuantity quantity, const config::Preset& preset, double sampleRate)
    : quantity_(quantity), bodyName_(listeningBodyName(preset))
{
    const physics::VoiceConfig reference;
    physics::BodyParameters body = physics::bodyByName(bodyName_);
    physics::applyRadiationGains(body, preset.radiationGains);
    body_.configure(body, sampleRate, 2.0 * std::numbers::pi * reference.maxModeFrequencyRatio * sampleRate);
}

double ListeningOutput::next(double bridgeForce) noexcept
{
    if (quantity_ == OutputQuantity::Force)
        return bridgeForce;
    body_.advance(bridgeForce);
    return quantity_ == OutputQuantity::Radiated ? body_.radiatedPressure() : body_.bridgeVelocity();
}

std::string ListeningOutput::describe() const
{
    switch (quantity_)
    {
    case OutputQuantity::Force:
        return "bridge force";
    case OutputQuantity::Velocity:
        return "bridge velocity of the " + bodyName_ + " body";
    case OutputQuantity::Radiated:
        break;
    }
    return "sound pressure at 1 m radiated by the " + bodyName_ + " body";
}

const char* ListeningOutput::unit() const noexcept
{
    switch (quantity_)
    {
    case OutputQuantity::Force:
        return "N";
    case OutputQuantity::Velocity:
        return "m/s";
    case OutputQuantity::Radiated:
        break;
    }
    return "Pa";
}

} // namespace rosin::cli
