#include "lab/discovery/DatasetReader.h"

#include <filesystem>

#include "core/config/JsonFile.h"
#include "lab/discovery/ChannelTable.h"
#include "lab/discovery/FieldChecks.h"
#include "lab/discovery/RigReader.h"
#include "lab/discovery/TrialReader.h"

namespace rosin::discovery
{

namespace fs = std::filesystem;
using config::describeJson;
using config::JsonObject;

namespace
{
constexpr Range kSampleRate{.min = 1000.0, .max = 384000.0, .unit = "Hz", .integer = true};
constexpr Range kHighpass{.min = 0.0, .unit = "Hz"};
constexpr Range kNoiseRms{.min = 0.0, .unit = "the unit of each channel"};

Channel parseChannel(const JsonObject& c, const std::vector<Channel>& earlier)
{
    Channel channel;
    channel.name = requiredString(c, "name");
    const auto kind = findChannelKind(channel.name);
    if (!kind)
        c.fail("name", "a channel name, " + config::oneOfText(channelNames()), describeJson(c.at("name")));
    for (std::size_t j = 0; j < earlier.size(); ++j)
        if (earlier[j].name == channel.name)
            // Two channels of one name would make "the bridgeForce channel" ambiguous.
            c.fail("name", "a channel not listed before",
                   describeJson(c.at("name")) + ", already channels[" + std::to_string(j) + "]");
    channel.unit = requiredString(c, "unit");
    if (channel.unit != kind->unit)
        c.fail("unit", "\"" + std::string(kind->unit) + "\" (the unit of " + channel.name + ")",
               describeJson(c.at("unit")));
    return channel;
}

std::vector<Channel> parseChannels(const JsonObject& root)
{
    const auto& array = requiredArray(root, "channels");
    std::vector<Channel> channels;
    bool hasResponse = false;
    for (std::size_t i = 0; i < array.size(); ++i)
    {
        channels.push_back(
            parseChannel(JsonObject(array[i], root.file(), elementPath("channels", i)), channels));
        hasResponse = hasResponse || findChannelKind(channels.back().name)->response;
    }
    if (!hasResponse)
    {
        std::string listed;
        for (const auto& c : channels)
            listed += (listed.empty() ? "" : ", ") + c.name;
        const auto names = responseChannelNames();
        root.fail("channels", "at least one of " + names[0] + ", " + names[1] + ", " + names[2],
                  "only " + listed);
    }
    return channels;
}

Sensor parseSensor(const JsonObject& root)
{
    Sensor sensor;
    if (!root.has("sensor"))
        return sensor;
    const JsonObject s = root.object("sensor");
    sensor.highpassHz = optionalNumber(s, "highpassHz", kHighpass);
    sensor.noiseRms = optionalNumber(s, "noiseRms", kNoiseRms);
    return sensor;
}
} // namespace

Dataset parseDatasetDescription(const nlohmann::json& root, const std::string& file,
                                const std::string& folder)
{
    config::requireFormat(root, file, kDatasetFormat);
    const JsonObject r(root, file, "");
    Dataset d;
    d.folder = folder;
    d.description = r.optionalString("description").value_or("");
    d.sampleRate = static_cast<int>(requiredNumber(r, "sampleRate", kSampleRate));
    d.channels = parseChannels(r);
    d.rig = parseRig(r);
    d.sensor = parseSensor(r);
    d.trials = parseTrials(r, d.channels, folder);
    return d;
}

Dataset readDatasetDescription(const std::string& folder)
{
    std::error_code ec;
    if (!fs::is_directory(folder, ec))
        throw DatasetError(folder, "", "a dataset folder holding dataset.json",
                           fs::exists(folder, ec) ? "a file, not a folder" : "no such folder");
    const std::string file = (fs::path(folder) / kDescriptionFile).string();
    return parseDatasetDescription(config::readJsonFile(file), file, folder);
}

} // namespace rosin::discovery
