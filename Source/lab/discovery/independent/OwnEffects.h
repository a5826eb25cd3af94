#pragma once
// The independent generator's forms of the catalog's effects (EffectCatalog.h names them). Each is a
// physically reasonable variant that is NOT the formula Rosin's catalog uses, so that rosin discover is
// tested on an effect it can only approximate:
//
//   junction-growth      saturating ageing of the static limit while stuck, reset by sliding:
//                        limit x (1 + gain (1 - exp(-t_hold / time)))       (catalog: logarithmic growth)
//   breakaway-jump       a cold breakaway: the static limit exceeds the plastic value by a margin that fades
//                        as the contact warms, limit x (1 + margin exp(-T / warmth)); sliding friction stays
//                        plastic, so the first slip releases with a jump   (catalog: [Woodhouse-thermal]'s
//                        modified law)
//   hertz-contact        contact area ~ F^exponent, equal to the Coulomb area at a reference force
//                        (catalog: exactly 2/3, referenced at the rig's 1 N)
//   sticking-creep       Bingham-like: a nominally stuck contact creeps only where the force exceeds a share
//                        of the static limit, at (|f| - share x limit) / resistance  (catalog: a dashpot
//                        in series from zero force)
//   extra-string-damping either a frequency-independent extra 1/Q, or only the bending (high-frequency)
//                        term of the loss law raised              (catalog: every mode's loss x a factor)
//   friction-law         the plan's law: viscous, as this generator's own viscous law (ContactFriction.h,
//                        its viscosity read from its own calibration table); the friction curves are not
//                        simulated here                    (catalog: Rosin's ViscousThermalLaw)
//   ambient-temperature  the rosin starts at the plan's offset; below ambient the yield stress rises along
//                        the table's own slope (YieldStressTable) (catalog: holds the ambient value)
//
// Own-form values are drawn from the dataset's seed (their own stream per effect), except the ambient offset
// and the law, which are the same physical choices as the catalog's and are taken from the plan.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace rosin::discovery
{

struct SynthPlan;

struct OwnEffects
{
    double growthGain = 0.0;      ///< junction growth: saturated fractional gain (0: off)
    double growthTime = 0.01;     ///< s
    double breakawayMargin = 0.0; ///< cold breakaway: fractional excess of the static limit (0: off)
    double breakawayWarmth = 4.0; ///< K over which the margin fades by e
    bool hertz = false;
    double hertzExponent = 2.0 / 3.0;
    double hertzReferenceForce = 1.0; ///< N
    double creepShare = 1.0;          ///< sticking creep above this share of the static limit
    double creepResistance = 0.0;     ///< N s/m (0: off)
    double extraEta = 0.0;            ///< extra frequency-independent 1/Q
    double bendingLossFactor = 1.0;   ///< factor on the loss law's bending term
    double ambientOffset = 0.0;       ///< K
    bool viscous = false;             ///< the viscous thermal law in place of the plastic one

    /// The drawn values as key/value pairs ("junction-growth.gain", 0.41), for the truth file.
    std::vector<std::pair<std::string, double>> values() const;
};

/// The own forms of the plan's hidden effects (plan.effects), drawn from plan.seed; the ambient offset is the
/// plan model's (which also carries a preset's own offset).
OwnEffects drawOwnEffects(const SynthPlan& plan);

/// Draw ranges, for tests and reports.
namespace own_ranges
{
inline constexpr double kGrowthGain[2] = {0.25, 0.6};
inline constexpr double kGrowthTime[2] = {0.005, 0.04}; ///< s, log-uniform
inline constexpr double kBreakawayMargin[2] = {0.15, 0.4};
inline constexpr double kBreakawayWarmth[2] = {2.0, 6.0}; ///< K
inline constexpr double kHertzExponent[2] = {0.62, 0.72};
inline constexpr double kHertzReference[2] = {0.6, 1.6}; ///< N, log-uniform
inline constexpr double kCreepShare[2] = {0.4, 0.7};
inline constexpr double kCreepResistance[2] = {15.0, 60.0}; ///< N s/m, log-uniform
inline constexpr double kExtraEta[2] = {4e-4, 1.2e-3};
inline constexpr double kBendingLossFactor[2] = {3.0, 6.0};
} // namespace own_ranges

} // namespace rosin::discovery
