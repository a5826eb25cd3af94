#pragma once
// From the instrument parameters (and the extras a factory program brings) to the physics'
// InstrumentConfig. Runs off the audio thread only.
#include <optional>

#include "core/config/Preset.h"
#include "core/physics/instrument/BowedInstrument.h"
#include "instrument/engine/EngineParameters.h"

namespace rosin::engine
{

/// What a factory program sets beyond the host parameters: the contact, the model switches, and the
/// preset's string (which replaces the instrument's string nearest in pitch: the Schumacher rig puts the
/// seed's 693 Hz E string on the violin).
struct ProgramExtras
{
    std::optional<config::Preset> preset; ///< absent: the instrument's own defaults
};

/// The instrument the parameters describe. Throws std::exception on an invalid preset (never for the
/// parameters themselves).
physics::InstrumentConfig buildInstrumentConfig(const InstrumentKey& key, const ProgramExtras& extras);

/// 0 (cello) or 1 (violin) for a preset: by its string's name ("violin-..."), else cello.
int instrumentIndexForPreset(const config::Preset& preset);

} // namespace rosin::engine
