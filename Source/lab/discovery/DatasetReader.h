#pragma once
// Reading and validating a dataset's description, dataset.json, in the format "rosin-measurements/1"
// (Resources/docs/measurements.md). Every file that follows the spec is accepted (unknown extra fields
// included); anything else throws DatasetError naming the file, the field and what was expected:
//     data/scan/dataset.json: field "trials[3].gesture.acceleration": expected a non-zero number (m/s^2) but
//     got nothing (the field is required)
#include <string>

#include <nlohmann/json.hpp>

#include "lab/discovery/Dataset.h"

namespace rosin::discovery
{

/// Reads FOLDER/dataset.json. The trial files are not opened (readTrialSignals does that), but their paths
/// are checked to stay inside the folder.
Dataset readDatasetDescription(const std::string& folder);
/// Validates an already parsed description; `file` names it in errors, `folder` is the dataset folder.
Dataset parseDatasetDescription(const nlohmann::json& root, const std::string& file,
                                const std::string& folder);

} // namespace rosin::discovery
