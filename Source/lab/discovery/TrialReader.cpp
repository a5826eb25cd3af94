#include "lab/discovery/TrialReader.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "lab/discovery/FieldChecks.h"
#include "lab/discovery/TrialPath.h"

namespace rosin::discovery
{

using config::describeJson;
using config::JsonObject;

namespace
{
constexpr Range kBeta{.min = 0.0, .max = 0.5, .minOpen = true, .maxOpen = true};
constexpr Range kBowForce{.min = 0.0, .unit = "N", .minOpen = true};
constexpr Range kAcceleration{.unit = "m/s^2", .nonZero = true};
constexpr Range kSpeed{.unit = "m/s", .nonZero = true};
// Integers a double holds exactly, so 3 and 3.0 mean the same repeat.
constexpr Range kRepeat{.min = -9007199254740992.0, .max = 9007199254740992.0, .integer = true};

bool isIdCharacter(char c)
{
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '_';
}

std::string parseId(const JsonObject& t)
{
    const std::string id = requiredString(t, "id");
    if (id.empty() || !std::all_of(id.begin(), id.end(), isIdCharacter))
        t.fail("id", "a non-empty id of letters, digits, '-' and '_'", describeJson(t.at("id")));
    return id;
}

std::string parseFile(const JsonObject& t, const std::filesystem::path& folder)
{
    const std::string file = requiredString(t, "file");
    if (const auto problem = trialFileProblem(folder, file))
        t.fail("file", "a path relative to the dataset folder, inside it",
               describeJson(t.at("file")) + ", " + *problem);
    return file;
}

Gesture parseGesture(const JsonObject& t, const std::vector<Channel>& channels)
{
    const JsonObject g = t.object("gesture");
    const std::vector<std::string> types{"constant-acceleration", "steady", "recorded"};
    if (!g.has("type"))
        g.fail("type", config::oneOfText(types), "nothing (the field is required)");
    const std::string type = *g.optionalOneOf("type", types);
    if (type == "constant-acceleration")
        return ConstantAcceleration{requiredNumber(g, "acceleration", kAcceleration)};
    if (type == "steady")
        return Steady{requiredNumber(g, "speed", kSpeed)};
    const bool hasBowVelocity = std::any_of(channels.begin(), channels.end(),
                                            [](const Channel& c) { return c.name == "bowVelocity"; });
    if (!hasBowVelocity)
        g.fail("type", "a bowVelocity entry in \"channels\" for a \"recorded\" gesture",
               "\"recorded\" but the dataset has no bowVelocity channel");
    return Recorded{};
}

Trial parseTrial(const JsonObject& t, const std::vector<Channel>& channels,
                 const std::filesystem::path& folder)
{
    Trial trial;
    trial.id = parseId(t);
    trial.file = parseFile(t, folder);
    trial.beta = requiredNumber(t, "beta", kBeta);
    trial.bowForce = requiredNumber(t, "bowForce", kBowForce);
    trial.gesture = parseGesture(t, channels);
    trial.valid = t.optionalBool("valid").value_or(true);
    trial.ambientTemperature = optionalNumber(t, "ambientTemperature", kCelsius);
    if (const auto repeat = optionalNumber(t, "repeat", kRepeat))
        trial.repeat = static_cast<std::int64_t>(*repeat);
    return trial;
}
} // namespace

std::vector<Trial> parseTrials(const JsonObject& root, const std::vector<Channel>& channels,
                               const std::filesystem::path& folder)
{
    const auto& array = requiredArray(root, "trials");
    std::vector<Trial> trials;
    std::map<std::string, std::size_t> firstIndex;
    for (std::size_t i = 0; i < array.size(); ++i)
    {
        const JsonObject t(array[i], root.file(), elementPath("trials", i));
        Trial trial = parseTrial(t, channels, folder);
        if (const auto [it, inserted] = firstIndex.emplace(trial.id, i); !inserted)
            t.fail("id", "an id no other trial has",
                   describeJson(t.at("id")) + ", as trials[" + std::to_string(it->second) + "] has");
        trials.push_back(std::move(trial));
    }
    return trials;
}

} // namespace rosin::discovery
