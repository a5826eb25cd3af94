#pragma once
// An instrument preset: which string, body, friction law and contact, and the model switches of
// [Galluzzo2017] Fig. 12 (torsion, bending stiffness). Slow parameters only; the bow gesture is separate.
// Stored as JSON "rosin-preset/1" (Resources/docs/presets.md); absent fields keep the Galluzzo-rig defaults
// below.
#include <optional>
#include <string>
#include <vector>

#include "core/physics/body/RadiationGains.h"
#include "core/physics/bow/BowParameters.h"
#include "core/physics/rig/OscillatorRigParameters.h"
#include "core/physics/string/StringParameters.h"
#include "core/physics/thermal/ContactParameters.h"

namespace rosin::config
{

/// Changes to the base contact's bowing geometry (ContactParameters::rig); absent members keep the base.
struct ContactOverrides
{
    std::optional<double> radius;         ///< a_ref, m
    std::optional<double> referenceForce; ///< N_ref, N
    std::optional<double> layerThickness; ///< delta, m
    std::optional<physics::ContactScaling> scaling;
};

/// [Smith2000]'s single-mode oscillator rig, bowed by a rod, in place of a string and body (preset field
/// "rig").
struct RigPreset
{
    physics::OscillatorRigParameters oscillator;
    double normalForce = physics::CantileverLoad::normalForce; ///< N: what `steady` without keys presses with
    double rodSpeed = physics::CantileverLoad::rodSpeed;       ///< m/s: what `steady` without keys moves at
};

/// How a program plays (the "player" object): the musical mapping and its settings; absent values keep the
/// host parameters' defaults (player::GestureParameters).
struct PlayerPreset
{
    std::string mapping = "musical"; ///< "lab" or "musical"
    std::optional<double> dynamics, bowPressure, vibratoDepth, vibratoRate, vibratoDelay, slideTime,
        tremoloRate;
    std::optional<std::string> articulation; ///< "arco" or "pizzicato"
};

struct Preset
{
    std::string name = "galluzzo-rig";
    std::string description;
    std::string source = "<built-in default>"; ///< the file it was read from (for error messages)
    /// Resolved string: a catalogue entry, or an inline object (possibly based on a catalogue entry).
    physics::StringParameters string = physics::stringFromCatalogue("cello-D3");
    std::string body = "cello";       ///< "cello", "violin" or "rigid"
    std::string friction = "plastic"; ///< a physics::frictionModelNames() entry
    std::string contact = "galluzzo"; ///< base contact: "galluzzo" or "schumacher" ([Galluzzo2017] Table 2)
    ContactOverrides contactOverrides;
    /// physics::rosinMaterialNames(): "handbook", or "calibrated" (rho c fixed by [Smith2000]'s 44 Hz,
    /// physics/thermal/RosinMaterial.h)
    std::string rosin = "handbook";
    bool torsion = true;          ///< torsional modes on ([Galluzzo2017] Fig. 12e turns them off)
    bool bendingStiffness = true; ///< EI on ([Galluzzo2017] Fig. 12f turns it off)
    physics::BowParameters bow;   ///< ribbon width and hair ("bow"); default the seeds' rod: a rigid point
    double ambientOffset = 0.0;   ///< K, rosin temperature at rest minus the calibration's ambient
    double beta = 0.0899;         ///< default bow position for gestures that do not set one
    /// dB, the plugin's output level for this program (its default -12 dB when absent): a calibration, set so
    /// that the demo phrase peaks near -6 dBFS (Resources/docs/playing.md, "Levels and clicks").
    std::optional<double> outputLevel;
    /// The plugin's measured body response for this program (absolute path of a WAV file; the file may give
    /// it relative to its own folder): bridge force (N) to sound pressure (Pa). Absent: the modal body.
    std::optional<std::string> bodyResponse;
    /// Gains on the body's radiated levels over frequency (RadiationGains.h; empty: the modelled body's): a
    /// calibration to a recording, as Resources/scripts/fit_body.py writes it.
    std::vector<physics::RadiationGainPoint> radiationGains;
    std::optional<RigPreset> rig;       ///< set: the rig is bowed instead of the string and body
    std::optional<PlayerPreset> player; ///< absent: the lab mapping (the lab programs)
};

/// The renderer's default: open cello D3 of the Galluzzo rig [Galluzzo2017], cello body, plastic friction,
/// Galluzzo contact, beta 0.0899 (presets/galluzzo-rig.json holds the same values).
inline Preset defaultPreset()
{
    return Preset{};
}

} // namespace rosin::config
