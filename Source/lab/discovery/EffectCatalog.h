#pragma once
// The catalog of physical effects the discrepancy workflow can name. Each is a real model
// component that the plugin and the scans can use too, reached through SimulationModel: rosin synth-data
// hides effects in a dataset with apply(), rosin discover tries the same apply() to explain a gap, so the
// two cannot disagree on what an effect is. JUCE-free.
//
//   junction-growth      contact ageing ([Notes §8.2]): the limiting static friction grows
//                        with the time spent sticking, mu_s(t_h) = mu_s0 (1 + growth ln(1 + t_h / tau_c));
//                        or saturating, mu_s0 (1 + growth (1 - exp(-t_h / tau_c)));
//                        physics::JunctionGrowthLaw around the preset's law. Parameters: growth
//                        (dimensionless, beta_a / mu_s0), onsetTime (tau_c, s), ageingForm (a choice).
//                        Fitted as (gain after a 50 ms hold, onsetTime, ageingForm): a Guettler scan's
//                        first slips pin the gain at their hold times (tens of ms), i.e. growth and onset
//                        only along a curve (growth x ln(1 + t / tau_c) about constant).
//   breakaway-jump       an abrupt release at the first slip while the rosin is cold: the modified thermal
//                        law of [Woodhouse-thermal] (eq. 6 with the jump curve of eq. 12 bow / eq. 13 rod)
//                        replaces the preset's law, or (jumpCurve "none") the preset's law stays; either way
//                        the contact at rest may hold firstSlipMargin more than the law's static limit until
//                        its first slip (physics::BreakawayMarginLaw: the jump's signature without a curve,
//                        so an effect is named by what it does, not by one formula). Parameters: jumpCurve, a
//                        choice of "rod", "bow" or "none"; firstSlipMargin (dimensionless).
//   hertz-contact        contact area ~ N^(2/3) (one elastic contact) instead of ~ N ([Notes §8.3];
//                        [Galluzzo2017] Fig. 11): the preset's contact scaling becomes Hertz. No parameter.
//   sticking-creep       viscous-like creep during nominal sticking ([Galluzzo2017] section 5.3): a dashpot
//   in
//                        series with the sticking contact, physics::StickingCreepLaw. Parameter:
//                        creepResistance (eta, N s/m; the pre-slip force is the rigid-sticking one times eta
//                        / (2Z + eta)); the creep's work f^2 / eta heats a thermal law's contact.
//   extra-string-damping string losses above the nominal loss law (as for a finger-stopped string,
//   [Galluzzo2017]
//                        Table 1 bracket and Fig. 12c). Parameters: lossScale (x) and lossTerms, a choice
//                        of which terms grow: all (VoiceConfig::lossScale), the internal friction eta_F
//                        only (frequency-independent), or the bending term eta_B only (high partials).
//   ambient-temperature  the rosin starts warmer or colder than the rig's stated ambient (the thermal laws of
//                        the three source texts read their calibrated tables at T + offset):
//                        Preset::ambientOffset. Parameter: ambientOffset (K). A colder rosin keeps its
//                        ambient properties until the contact has warmed by |offset| (the calibration does
//                        not extend below ambient).
//   friction-law         another law of the three source texts in the baseline's place ([Woodhouse-thermal]
//                        asks which law describes rosin; a dataset may answer with another than the
//                        baseline's): the plastic or viscous thermal law ([Smith2000] eqs. 4, 3) or the
//                        classical or reconstructed friction curve ([Galluzzo2017] eqs. 1, 2). Parameter:
//                        replacementLaw, a choice; its null is the law the model already has. The modified
//                        law is breakaway-jump's (a jump curve with no margin), so it is not a choice here.
//                        Fitted like every effect, with the calibration's nuisance refitted within its
//                        priors; the curves take none of the rosin's thermal constants.
//
// Parameter names are deliberately distinct words (no "eta", "tau"): a dataset must not name its hidden
// effect, and tests check that by searching the dataset's files for every effect and parameter name.
#include <string>
#include <vector>

#include "lab/discovery/EffectParameter.h"
#include "lab/discovery/SimulationModel.h"

namespace rosin::discovery
{

struct Effect
{
    std::string name;    ///< "junction-growth", ...
    std::string summary; ///< one line: the physics
    std::string source;  ///< where the physics comes from ("[Notes §8.2]")
    std::vector<EffectParameter> parameters;
    /// Changes `model` as the header describes; `values` in parameter order, already checked.
    void (*change)(SimulationModel& model, const std::vector<double>& values);
    /// The coordinates rosin discover's fit searches where they are not `parameters` themselves (empty: they
    /// are; else as many, choices in the same places), and the map from a point of them to the parameters'
    /// values. For parameters that the data pin only in a combination: the fit steps along one coordinate
    /// at a time, which crosses a valley lying diagonally to them without following it.
    std::vector<EffectParameter> searchParameters{};
    std::vector<double> (*fromSearch)(const std::vector<double>& searchValues) = nullptr;
    /// True where `values` leave the model `before` them as it was, the effect absent (its null: no growth,
    /// no margin and no curve, no extra loss, no offset, the law it already has); nullptr for an effect
    /// without one in its fit range (hertz contact is a switch; the weakest creep still moves a bowed
    /// transient). A fit that ends at its null explains nothing of its own: discover says so.
    bool (*atNull)(const std::vector<double>& values, const SimulationModel& before) = nullptr;
};

/// The coordinates a fit of `effect` searches: searchParameters, or parameters where there are none.
const std::vector<EffectParameter>& fitCoordinates(const Effect& effect);
/// The effect's parameter values at a point of its fit coordinates.
std::vector<double> parameterValues(const Effect& effect, const std::vector<double>& searchValues);

/// Whether `values` of `effect` leave `before` as it was (Effect::atNull; false for an effect without one).
bool isNull(const Effect& effect, const std::vector<double>& values, const SimulationModel& before = {});

/// The seven effects, in the order they were specified (reports and tests list them so).
const std::vector<Effect>& effectCatalog();
/// Their names, in that order.
std::vector<std::string> effectNames();
/// The effect of that name, or nullptr.
const Effect* findEffect(const std::string& name);
/// Its place in the catalog (stable: it seeds the effect's random stream in rosin synth-data).
std::size_t effectIndex(const Effect& effect);

/// Checks the values (count, finite, in range, choices whole) and changes the model. Throws
/// std::invalid_argument naming the effect, the parameter and its range.
void applyEffect(const Effect& effect, const std::vector<double>& values, SimulationModel& model);

/// A value as text: the choice's name, or the number with its unit ("0.0054 s").
std::string formatParameterValue(const EffectParameter& parameter, double value);
/// "junction-growth: growth = 0.21, onsetTime = 0.0054 s" ("hertz-contact" alone without parameters).
std::string describeEffect(const Effect& effect, const std::vector<double>& values);

} // namespace rosin::discovery
