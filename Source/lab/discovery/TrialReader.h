#pragma once
// The "trials" array of dataset.json: ids, files inside the folder, beta, force and gesture of every trial.
#include <filesystem>
#include <vector>

#include "core/config/JsonObject.h"
#include "lab/discovery/Dataset.h"

namespace rosin::discovery
{

/// Parses root["trials"]. `channels` are the dataset's (a recorded gesture needs a bowVelocity channel) and
/// `folder` the dataset folder the trial files must stay inside. Throws DatasetError naming the field
/// ("trials[3].gesture.acceleration").
std::vector<Trial> parseTrials(const config::JsonObject& root, const std::vector<Channel>& channels,
                               const std::filesystem::path& folder);

} // namespace rosin::discovery
