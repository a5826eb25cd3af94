#pragma once
// What `rosin render --gesture` writes to --out (--output): the sound the body radiates to a listener at 1 m
// (default, as the plugin), the bridge force, or the bridge velocity. The body is driven one way by the
// voice's bridge force: the body is linear, so its state equals the one coupled to the string sample for
// sample. On a rigid bridge the listener hears the string through the body of its instrument family.
#include <string>
#include <vector>

#include "core/config/Preset.h"
#include "core/physics/body/BridgeBody.h"

namespace rosin::cli
{

enum class OutputQuantity
{
    Radiated,
    Force,
    Velocity
};

/// "radiated", "force", "velocity": the --output choices, in OutputQuantity's order.
const std::vector<std::string>& outputQuantityNames();
/// One of outputQuantityNames(); throws config::ConfigError naming --output otherwise.
OutputQuantity outputQuantityFromName(const std::string& name);

class ListeningOutput
{
  public:
    /// Off the audio path: configures the body for `preset` (its own, or its family's when rigid).
    ListeningOutput(OutputQuantity quantity, const config::Preset& preset, double sampleRate);
    /// The output for this sample's bridge force (N).
    double next(double bridgeForce) noexcept;
    /// "radiated sound pressure at 1 m through the cello body", ... for the command's report.
    std::string describe() const;
    /// "Pa", "N" or "m/s".
    const char* unit() const noexcept;

  private:
    OutputQuantity quantity_;
    std::string bodyName_;
    physics::BridgeBody body_;
};

} // namespace rosin::cli
