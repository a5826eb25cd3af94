#pragma once
// The "rig" object of dataset.json: the string (with cello-D3 defaults for what is absent), body, bow and
// ambient temperature.
#include "core/config/JsonObject.h"
#include "lab/discovery/Dataset.h"

namespace rosin::discovery
{

/// Parses root["rig"]; throws DatasetError naming the field ("rig.string.tension") on anything invalid.
Rig parseRig(const config::JsonObject& root);

} // namespace rosin::discovery
