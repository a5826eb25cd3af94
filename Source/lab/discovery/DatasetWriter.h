#pragma once
// Writing a dataset's description, dataset.json, so that readDatasetDescription accepts it and gives back the
// same Dataset (unknown extra fields of a file that was read are not kept).
#include <string>

#include <nlohmann/json.hpp>

#include "lab/discovery/Dataset.h"

namespace rosin::discovery
{

/// The description as JSON, members in the spec's order. rig.string holds the fields that were given, not
/// the cello-D3 defaults, so a round trip keeps Rig::defaultedStringFields.
nlohmann::ordered_json datasetToJson(const Dataset& dataset);
/// Writes FOLDER/dataset.json (creating the folder). The text is validated with the reader first, so an
/// invalid dataset throws DatasetError naming the field and nothing is written; a write failure throws too.
void writeDatasetDescription(const Dataset& dataset, const std::string& folder);

} // namespace rosin::discovery
