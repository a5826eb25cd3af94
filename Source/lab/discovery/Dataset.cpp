#include "lab/discovery/Dataset.h"

#include <filesystem>

#include "core/gesture/GestureLimits.h"
#include "lab/discovery/StringFields.h"

namespace rosin::discovery
{

std::string gestureTypeName(const Gesture& gesture)
{
    if (std::holds_alternative<ConstantAcceleration>(gesture))
        return "constant-acceleration";
    if (std::holds_alternative<Steady>(gesture))
        return "steady";
    return "recorded";
}

std::optional<std::size_t> Dataset::channelIndex(const std::string& name) const
{
    for (std::size_t i = 0; i < channels.size(); ++i)
        if (channels[i].name == name)
            return i;
    return std::nullopt;
}

std::optional<std::size_t> Dataset::trialIndex(const std::string& id) const
{
    for (std::size_t i = 0; i < trials.size(); ++i)
        if (trials[i].id == id)
            return i;
    return std::nullopt;
}

std::optional<double> Dataset::ambientTemperature(const Trial& trial) const
{
    return trial.ambientTemperature ? trial.ambientTemperature : rig.ambientTemperature;
}

std::string Dataset::descriptionPath() const
{
    return (std::filesystem::path(folder) / kDescriptionFile).string();
}

namespace
{
double stringField(const physics::StringParameters& s, const std::string& name)
{
    for (const auto& field : stringFields())
        if (name == field.name)
            return s.*field.member;
    return 0.0;
}
} // namespace

std::string describeStringDefaults(const Rig& rig)
{
    if (rig.defaultedStringFields.empty())
        return {};
    std::string text = "rig.string: ";
    for (std::size_t i = 0; i < rig.defaultedStringFields.size(); ++i)
    {
        const auto& name = rig.defaultedStringFields[i];
        text += (i ? ", " : "") + name + " = " + physics::formatNumber(stringField(rig.string, name));
    }
    return text + " taken from the catalogue string " + std::string(kDefaultString);
}

} // namespace rosin::discovery
