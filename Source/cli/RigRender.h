#pragma once
// `rosin render --preset NAME` for a preset with a "rig" ([Smith2000]'s single-mode oscillator bowed by a
// rod): the same gesture, friction law, contact, WAV, probe and loop options as for a string, with the rig's
// own outputs. Chosen by RenderCommand when the preset has a rig.
#include <optional>
#include <ostream>
#include <string>

#include "cli/LoopOutput.h"
#include "core/config/Preset.h"
#include "core/config/VoiceSetup.h"
#include "core/gesture/BowGesture.h"

namespace rosin::cli
{

struct RigRenderRequest
{
    std::string gesture; ///< the spec as given (for the log and the figure title)
    double sampleRate = 48000.0;
    std::string out;
    std::optional<std::string> probe;
    std::optional<double> scale;
    std::optional<LoopRequest> loop;
};

/// `steady` without keys on a rig: the rig's own load and rod speed for one second.
std::string rigSteadyGesture(const config::RigPreset& rig);
/// Renders `bow` (prepared) through the preset's rig. Returns the exit status.
int renderRig(const config::Preset& preset, const config::VoiceSetup& setup, gesture::BowGesture& bow,
              double gestureSeconds, const RigRenderRequest& request, std::ostream& out, std::ostream& err);
/// The usage lines of the rig's outputs, for `rosin render --help`.
std::string rigRenderHelp();

} // namespace rosin::cli
