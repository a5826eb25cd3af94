// Measured datasets' descriptions ("rosin-measurements/1", dataset.json): JSON text -> validated Dataset.
#include "core/config/JsonFile.h"
#include "fuzz/FuzzTarget.h"
#include "lab/discovery/DatasetReader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace rosin;
    try
    {
        const auto root = config::parseJsonText(fuzz::asText(data, size), "dataset.json");
        const discovery::Dataset dataset =
            discovery::parseDatasetDescription(root, "dataset.json", "fuzzdata");
        for (const auto& trial : dataset.trials)
        {
            fuzz::requireFinite(trial.beta, "trial beta");
            fuzz::requireFinite(trial.bowForce, "trial bow force");
        }
    }
    catch (const discovery::DatasetError&)
    {
    }
    return 0;
}
