#include "lab/discovery/DatasetWriter.h"

#include <algorithm>
#include <filesystem>

#include "core/config/AtomicFile.h"
#include "lab/discovery/DatasetReader.h"
#include "lab/discovery/StringFields.h"

namespace rosin::discovery
{

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

namespace
{
Json gestureToJson(const Gesture& gesture)
{
    Json g;
    g["type"] = gestureTypeName(gesture);
    if (const auto* a = std::get_if<ConstantAcceleration>(&gesture))
        g["acceleration"] = a->acceleration;
    else if (const auto* s = std::get_if<Steady>(&gesture))
        g["speed"] = s->speed;
    return g;
}

Json rigToJson(const Rig& rig)
{
    Json string = Json::object();
    const auto& defaulted = rig.defaultedStringFields;
    for (const auto& field : stringFields())
        if (std::find(defaulted.begin(), defaulted.end(), field.name) == defaulted.end())
            string[field.name] = rig.string.*field.member;
    Json r;
    r["string"] = string;
    if (rig.body)
        r["body"] = *rig.body;
    if (!rig.bow.is_null())
        r["bow"] = Json::parse(rig.bow.dump());
    if (rig.ambientTemperature)
        r["ambientTemperature"] = *rig.ambientTemperature;
    return r;
}

Json trialToJson(const Trial& trial)
{
    Json t;
    t["id"] = trial.id;
    t["file"] = trial.file;
    t["beta"] = trial.beta;
    t["bowForce"] = trial.bowForce;
    t["gesture"] = gestureToJson(trial.gesture);
    t["valid"] = trial.valid;
    if (trial.ambientTemperature)
        t["ambientTemperature"] = *trial.ambientTemperature;
    if (trial.repeat)
        t["repeat"] = *trial.repeat;
    return t;
}
} // namespace

Json datasetToJson(const Dataset& dataset)
{
    Json root;
    root["format"] = kDatasetFormat;
    if (!dataset.description.empty())
        root["description"] = dataset.description;
    root["sampleRate"] = dataset.sampleRate;
    root["channels"] = Json::array();
    for (const auto& c : dataset.channels)
        root["channels"].push_back(Json{{"name", c.name}, {"unit", c.unit}});
    root["rig"] = rigToJson(dataset.rig);
    if (dataset.sensor.highpassHz || dataset.sensor.noiseRms)
    {
        Json sensor = Json::object();
        if (dataset.sensor.highpassHz)
            sensor["highpassHz"] = *dataset.sensor.highpassHz;
        if (dataset.sensor.noiseRms)
            sensor["noiseRms"] = *dataset.sensor.noiseRms;
        root["sensor"] = sensor;
    }
    root["trials"] = Json::array();
    for (const auto& t : dataset.trials)
        root["trials"].push_back(trialToJson(t));
    return root;
}

void writeDatasetDescription(const Dataset& dataset, const std::string& folder)
{
    const std::string file = (fs::path(folder) / kDescriptionFile).string();
    const std::string text = datasetToJson(dataset).dump(2) + "\n";
    // Never write what the reader would reject: the error names the field as a read would.
    parseDatasetDescription(nlohmann::json::parse(text), file, folder);

    std::error_code ec;
    fs::create_directories(folder, ec);
    if (ec)
        throw DatasetError(folder, "", "a folder that can be created", ec.message());
    config::writeFileAtomically(file, text);
}

} // namespace rosin::discovery
