#pragma once
// A scan specification as JSON ("rosin-scan-spec/1"), stored as DIR/scan.spec.json (or next to a shard's
// rows) so that a resumed run or a merge can prove its rows belong to the same scan. The text is canonical
// (sorted keys, shortest round-trip numbers): two specs are the same scan exactly when their texts are equal,
// and specFromJson(specToJson(s)) rebuilds the same model and grid bit for bit.
#include <string>

#include <nlohmann/json.hpp>

#include "lab/scan/ScanSpec.h"

namespace rosin::scan
{

nlohmann::json specToJson(const ScanSpec& spec);
/// Throws config::ConfigError naming `file` and the field if the document is not a valid specification.
ScanSpec specFromJson(const nlohmann::json& json, const std::string& file);
/// The file's text: specToJson(spec).dump(2) and a newline.
std::string specText(const ScanSpec& spec);
/// Parses a specification file's text (config::ConfigError naming `file` on failure).
ScanSpec specFromText(const std::string& text, const std::string& file);
/// What differs between two specification texts, for error messages: the differing top-level fields with
/// both values (shortened), e.g. `friction: "plastic" vs "classical"`.
std::string describeSpecDifference(const std::string& ours, const std::string& theirs);

} // namespace rosin::scan
