#pragma once
// Builds a friction law by its command-line / preset name.
#include <memory>
#include <string>
#include <vector>

#include "core/physics/friction/FrictionLaw.h"
#include "core/physics/thermal/ContactParameters.h"

namespace rosin::physics
{

/// The six laws of the seeds.
enum class FrictionModel
{
    Classical,     ///< seed 001 eq. 1, friction curve with hysteresis rule
    Reconstructed, ///< seed 001 eq. 2, friction curve with hysteresis rule
    Plastic,       ///< seed 000 eq. 4 as used in seed 001: mu = tau_y(T) A / Fb
    Viscous,       ///< seed 000 eq. 3: f = -eta(T) A dv / delta
    ModifiedBow,   ///< seed 002 eq. 6 with the bow jump curve (eq. 12)
    ModifiedRod    ///< seed 002 eq. 6 with the rod jump curve (eq. 13)
};
/// How many there are (the enum's values are 0 .. kFrictionModelCount - 1).
inline constexpr int kFrictionModelCount = static_cast<int>(FrictionModel::ModifiedRod) + 1;

/// "classical", "reconstructed", "plastic", "viscous", "modified-bow", "modified-rod".
const char* frictionModelName(FrictionModel model);
std::vector<std::string> frictionModelNames();
/// Parses a name; throws std::invalid_argument listing the valid names.
FrictionModel frictionModelFromName(const std::string& name);
/// A new, unprepared law. Thermal laws use `contact`; curve laws ignore it.
std::unique_ptr<FrictionLaw> makeFrictionLaw(FrictionModel model, const ContactParameters& contact);

} // namespace rosin::physics
