#pragma once
// One built instrument and what a front end shows of it: the physics' BowedInstrument for a parameter key and
// a program's extras, with its strings' open frequencies and the quantities of the Schelleng diagram. Built
// off the audio thread (allocates); the plugin hands it over with EngineSlot, the offline render keeps it.
#include <array>
#include <memory>

#include "core/physics/instrument/BowedInstrument.h"
#include "core/physics/laws/FrictionLimits.h"
#include "instrument/engine/EngineParameters.h"
#include "instrument/engine/InstrumentSetup.h"
#include "instrument/player/PlayableBand.h"

namespace rosin::engine
{

struct Engine
{
    InstrumentKey key;
    int programGeneration = 0; ///< which program's extras it was built with
    long serial = 0; ///< unique per build, so the audio thread notices a new engine (no ABA on addresses)
    double sampleRate = 48000.0;
    physics::BowedInstrument instrument;
    std::array<double, 8> openFrequencies{};
    std::array<double, 8> impedances{};          ///< Z0 per string, kg/s (editor's Schelleng diagram)
    std::array<double, 8> bridgeConductances{};  ///< per string, s/kg (schellengConductance)
    std::array<double, 8> forceShares{};         ///< per string, bowForceShare of its Z0
    std::array<player::PlayableBand, 8> bands{}; ///< per string, for the musical mapping (playableBand)
};

/// The string whose impedance the Bow force parameter refers to: the cello's C string.
inline constexpr const char* kBowForceReferenceString = "cello-C2";

/// The share of the Bow force parameter a string of impedance Z0 (kg/s) is bowed with: Z0 over the reference
/// string's, as a player's arm lightens on thinner strings. Schelleng's maximum force is 2 Z0 v_b / (beta
/// (mu_s - mu_d)), so every string, on either instrument, plays at the same fraction of it and is flattened
/// alike by the force (the flattening grows with that fraction). One force for all strings had put the
/// cello's open A 20 cents flat and the violin's open D 37 cents flat at the default 1 N.
double bowForceShare(double impedance);

/// String i's playable band: its Z0, schellengConductance and the friction law's limits
/// (physics::frictionLimits).
player::PlayableBand playableBand(const physics::InstrumentConfig& config, std::size_t i,
                                  const physics::FrictionLimits& friction);

/// Builds and prepares the instrument of `key` with `extras` at `sampleRate`. A program whose extras do not
/// build (an invalid preset) is reported on stderr and the instrument's defaults are used.
std::unique_ptr<Engine> buildEngine(const InstrumentKey& key, const ProgramExtras& extras,
                                    int programGeneration, long serial, double sampleRate);

/// Loss at string i's ends as a bridge conductance G (s/kg), for the editor's Schelleng diagram.
double schellengConductance(const physics::InstrumentConfig& config, std::size_t i);

} // namespace rosin::engine
