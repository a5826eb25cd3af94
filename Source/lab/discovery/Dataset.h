#pragma once
// A measured dataset in the format "rosin-measurements/1" (Resources/docs/measurements.md): the rig, the
// channels of every trial file and the trials themselves. Plain data, JUCE-free; DatasetReader fills it from
// dataset.json and DatasetWriter writes it back.
#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/config/ConfigError.h"
#include "core/physics/string/StringParameters.h"

namespace rosin::discovery
{

/// Every reader error names the file, the JSON field path and what was expected (see config::ConfigError).
using DatasetError = config::ConfigError;

/// The format string a dataset.json must carry.
inline constexpr const char* kDatasetFormat = "rosin-measurements/1";
/// The description file inside a dataset folder.
inline constexpr const char* kDescriptionFile = "dataset.json";

/// One channel of the trial files, in file order: `name` from the spec's table, `unit` its unit ("N", "m/s").
struct Channel
{
    std::string name;
    std::string unit;
    bool operator==(const Channel&) const = default;
};

/// {"type":"constant-acceleration","acceleration":a}: the bow starts from rest, a in m/s^2.
struct ConstantAcceleration
{
    double acceleration = 0.0;
    bool operator==(const ConstantAcceleration&) const = default;
};
/// {"type":"steady","speed":v}: the bow moves at v m/s from t = 0.
struct Steady
{
    double speed = 0.0;
    bool operator==(const Steady&) const = default;
};
/// {"type":"recorded"}: the bow velocity is the trial's bowVelocity channel.
struct Recorded
{
    bool operator==(const Recorded&) const = default;
};
using Gesture = std::variant<ConstantAcceleration, Steady, Recorded>;

/// The spec's name of a gesture type: "constant-acceleration", "steady" or "recorded".
std::string gestureTypeName(const Gesture& gesture);

struct Trial
{
    std::string id;   ///< unique, [A-Za-z0-9_-]+
    std::string file; ///< as written in dataset.json: relative to the dataset folder, inside it
    double beta = 0.0;
    double bowForce = 0.0; ///< N
    Gesture gesture;
    bool valid = true;                        ///< false: kept but not scored
    std::optional<double> ambientTemperature; ///< deg C, overrides the rig's
    std::optional<std::int64_t> repeat;
    bool operator==(const Trial&) const = default;
};

struct Rig
{
    /// tension, massPerLength and length as measured; the other fields from the file or, where absent, from
    /// the catalogue string cello-D3 (listed in defaultedStringFields). stoppedLossF = lossF: the dataset's
    /// length is already the vibrating length, so the string is simulated open.
    physics::StringParameters string;
    /// Names of rig.string fields the file left out, in spec order ("bendingStiffness", "lossF", ...).
    std::vector<std::string> defaultedStringFields;
    std::optional<std::string> body;          ///< "cello", "rigid", or a body description path (kept as text)
    nlohmann::json bow;                       ///< free description; null when absent
    std::optional<double> ambientTemperature; ///< deg C, the default for trials
};

struct Sensor
{
    std::optional<double> highpassHz;
    std::optional<double> noiseRms; ///< in the unit of each channel
};

struct Dataset
{
    std::string folder;      ///< the dataset folder as given to the reader (trial files are relative to it)
    std::string description; ///< free text; empty when absent
    int sampleRate = 0;
    std::vector<Channel> channels;
    Rig rig;
    Sensor sensor;
    std::vector<Trial> trials;

    /// Index of the channel of that name, or std::nullopt.
    std::optional<std::size_t> channelIndex(const std::string& name) const;
    /// Index of the trial with that id, or std::nullopt.
    std::optional<std::size_t> trialIndex(const std::string& id) const;
    /// The trial's ambient temperature, else the rig's, else std::nullopt.
    std::optional<double> ambientTemperature(const Trial& trial) const;
    /// The path of dataset.json inside the folder.
    std::string descriptionPath() const;
};

/// Which rig.string fields came from cello-D3, as one sentence for logs and reports ("" when none):
/// "rig.string: bendingStiffness = 0.0003, lossF = 23 taken from the catalogue string cello-D3".
std::string describeStringDefaults(const Rig& rig);

} // namespace rosin::discovery
