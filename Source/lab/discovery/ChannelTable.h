#pragma once
// The spec's table of channel names and their units. One table so the reader, the writer and the WAV code
// agree on what a channel means.
#include <optional>
#include <string>
#include <vector>

namespace rosin::discovery
{

struct ChannelKind
{
    const char* name;
    const char* unit;
    /// bridgeForce, frictionForce and bowPointVelocity: a dataset needs at least one of them to be scored.
    bool response;
};

/// The five channel kinds of format version 1, in the spec's order.
const std::vector<ChannelKind>& channelKinds();
/// The kind of that name, or std::nullopt for an unknown name.
std::optional<ChannelKind> findChannelKind(const std::string& name);
/// The channel names, for "expected one of ..." messages.
std::vector<std::string> channelNames();
/// The names of the response channels ("bridgeForce, frictionForce or bowPointVelocity").
std::vector<std::string> responseChannelNames();

} // namespace rosin::discovery
