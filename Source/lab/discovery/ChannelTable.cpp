#include "lab/discovery/ChannelTable.h"

namespace rosin::discovery
{

const std::vector<ChannelKind>& channelKinds()
{
    static const std::vector<ChannelKind> kinds{
        {"bridgeForce", "N", true},    {"frictionForce", "N", true},     {"bowPointVelocity", "m/s", true},
        {"bowVelocity", "m/s", false}, {"bowForceMeasured", "N", false},
    };
    return kinds;
}

std::optional<ChannelKind> findChannelKind(const std::string& name)
{
    for (const auto& kind : channelKinds())
        if (name == kind.name)
            return kind;
    return std::nullopt;
}

std::vector<std::string> channelNames()
{
    std::vector<std::string> names;
    for (const auto& kind : channelKinds())
        names.emplace_back(kind.name);
    return names;
}

std::vector<std::string> responseChannelNames()
{
    std::vector<std::string> names;
    for (const auto& kind : channelKinds())
        if (kind.response)
            names.emplace_back(kind.name);
    return names;
}

} // namespace rosin::discovery
