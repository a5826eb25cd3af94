#pragma once
// Builds a friction law by its command-line / preset name.
#include <memory>
#include <string>
#include <vector>

#include "core/physics/friction/FrictionLaw.h"
#include "core/physics/thermal/ContactParameters.h"

namespace rosin::physics
{

/// The six laws of the three source texts ([Smith2000], [Galluzzo2017], [Woodhouse-thermal]).
enum class FrictionModel
{
    Classical,     ///< [Galluzzo2017] eq. 1, friction curve with hysteresis rule
    Reconstructed, ///< [Galluzzo2017] eq. 2, friction curve with hysteresis rule
    Plastic,       ///< [Smith2000] eq. 4 as used in [Galluzzo2017]: mu = tau_y(T) A / Fb
    Viscous,       ///< [Smith2000] eq. 3: f = -eta(T) A dv / delta
    ModifiedBow,   ///< [Woodhouse-thermal] eq. 6 with the bow jump curve (eq. 12)
    ModifiedRod    ///< [Woodhouse-thermal] eq. 6 with the rod jump curve (eq. 13)
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
