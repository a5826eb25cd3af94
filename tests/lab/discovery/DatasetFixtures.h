#pragma once
// The spec's example dataset.json (Resources/docs/measurements.md, copied verbatim) and a scratch dataset
// folder to write variants of it into.
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "core/config/TempFiles.h"

namespace rosin::test
{

inline const char* const kSpecExample = R"json({
  "format": "rosin-measurements/1",
  "description": "Guettler scan, cello D string, rosin-coated acrylic rod",
  "sampleRate": 44100,
  "channels": [
    { "name": "bridgeForce", "unit": "N" },
    { "name": "bowVelocity", "unit": "m/s" }
  ],
  "rig": {
    "string": {
      "tension": 111.0, "massPerLength": 0.0027, "length": 0.69,
      "bendingStiffness": 3.0e-4,
      "lossF": 23, "lossB": 12.5, "lossA": 0.11,
      "torsionalWaveSpeed": 758, "torsionalQ": 45, "torsionalImpedance": 1.8
    },
    "body": "cello",
    "bow": { "kind": "rod", "diameter": 0.013, "material": "acrylic" },
    "ambientTemperature": 20.0
  },
  "sensor": { "highpassHz": 0.5, "noiseRms": 0.002 },
  "trials": [
    {
      "id": "b0899-f03-a10",
      "file": "trials/b0899-f03-a10.wav",
      "beta": 0.0899,
      "bowForce": 0.84,
      "gesture": { "type": "constant-acceleration", "acceleration": 1.56 },
      "valid": true
    }
  ]
})json";

inline nlohmann::json specExample()
{
    return nlohmann::json::parse(kSpecExample);
}

/// A temporary dataset folder; describe() writes its dataset.json.
class DatasetFolder
{
  public:
    std::string path() const { return dir_.path(); }
    std::string descriptionPath() const
    {
        return (std::filesystem::path(dir_.path()) / "dataset.json").string();
    }
    void describe(const std::string& text) const { dir_.write("dataset.json", text); }
    void describe(const nlohmann::json& json) const { describe(json.dump(2)); }

  private:
    TempDir dir_;
};

} // namespace rosin::test
