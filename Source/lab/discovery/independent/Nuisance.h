#pragma once
// What a laboratory knows only to a tolerance: the real rig differs from the handbook values that
// dataset.json states. Drawn once per dataset from its seed (uniform within each tolerance) and applied to
// the simulated rig; the dataset keeps the nominal values.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/physics/string/StringParameters.h"

namespace rosin::discovery
{

struct Nuisance
{
    double contactRadius = 1.0;                   ///< x the bowing contact's reference radius (+-15 %)
    double rosinConductivity = 1.0;               ///< x rosin's K (layer and string coat; +-10 %)
    double rosinHeatCapacity = 1.0;               ///< x rosin's rho c (+-10 %)
    double lossF = 1.0, lossB = 1.0, lossA = 1.0; ///< x each string loss coefficient (+-10 %)
    double tension = 1.0;                         ///< x P (+-2 %)
    double massPerLength = 1.0;                   ///< x m (+-1 %)

    std::vector<std::pair<std::string, double>> values() const;
    /// The string as it really is.
    physics::StringParameters apply(physics::StringParameters nominal) const;
};

Nuisance drawNuisance(std::uint64_t seed);

/// Tolerances (relative half-widths), for tests and reports.
namespace nuisance_tolerance
{
inline constexpr double kContactRadius = 0.15;
inline constexpr double kRosin = 0.10;
inline constexpr double kLoss = 0.10;
inline constexpr double kTension = 0.02;
inline constexpr double kMass = 0.01;
} // namespace nuisance_tolerance

} // namespace rosin::discovery
