#include "lab/discovery/EffectCatalog.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>

#include "core/gesture/GestureLimits.h"

namespace rosin::discovery
{

namespace
{
// --- what each effect changes (the header says why) ----------------------------------------------------
void junctionGrowth(SimulationModel& m, const std::vector<double>& v)
{
    m.frictionEffects.junctionGrowth = v[0];
    m.frictionEffects.junctionGrowthTime = v[1];
    m.frictionEffects.junctionGrowthSaturates = v[2] == 1.0;
}

void breakawayJump(SimulationModel& m, const std::vector<double>& v)
{
    if (v[0] == 0.0)
        m.preset.friction = "modified-rod";
    else if (v[0] == 1.0)
        m.preset.friction = "modified-bow";
    m.frictionEffects.breakawayMargin = v[1];
}

void hertzContact(SimulationModel& m, const std::vector<double>&)
{
    m.preset.contactOverrides.scaling = physics::ContactScaling::Hertz;
}

void stickingCreep(SimulationModel& m, const std::vector<double>& v)
{
    m.frictionEffects.creepResistance = v[0];
}

// Junction growth's fit coordinates: the static limit's fractional gain after kReferenceHold instead of
// `growth` (the header says why). 50 ms: the median first hold of a Guettler scan from rest (measured: 15 ms
// to 0.3 s, median 46 ms, on the suite's 8 x 8 set).
constexpr double kReferenceHold = 0.05; // s

double ageingShape(double tau, bool saturating)
{
    const double x = kReferenceHold / tau;
    return saturating ? -std::expm1(-x) : std::log1p(x);
}

std::vector<double> junctionGrowthFromSearch(const std::vector<double>& s)
{
    const double growth = std::min(s[0] / ageingShape(s[1], s[2] == 1.0), 1.0); // the catalog's fit range
    return {growth, s[1], s[2]};
}

// Multiplies, so the effect adds to whatever loss the baseline already has: every term of the loss law, or
// only its internal-friction term (frequency-independent) or only its bending term (high partials).
void extraStringDamping(SimulationModel& m, const std::vector<double>& v)
{
    if (v[1] == 1.0)
    {
        m.preset.string.lossF *= v[0];
        m.preset.string.stoppedLossF *= v[0];
    }
    else if (v[1] == 2.0)
        m.preset.string.lossB *= v[0];
    else
        m.lossScale *= v[0];
}

// The seeds' laws a candidate may put in the baseline's place, in the order of its choice. The modified law
// is breakaway-jump's (its curves with no margin), so it is not repeated here.
constexpr const char* kReplacementLaws[] = {"plastic", "viscous", "classical", "reconstructed"};

void frictionLawSwap(SimulationModel& m, const std::vector<double>& v)
{
    m.preset.friction = kReplacementLaws[static_cast<std::size_t>(v[0])];
}

// Adds, for the same reason: the offset is relative to the rig's stated ambient.
void ambientTemperature(SimulationModel& m, const std::vector<double>& v)
{
    m.preset.ambientOffset += v[0];
}

// Each effect's null: the values at which its change leaves the model as it was.
bool junctionGrowthNull(const std::vector<double>& v, const SimulationModel&)
{
    return v[0] == 0.0;
}

bool breakawayNull(const std::vector<double>& v, const SimulationModel&)
{
    return v[0] == 2.0 && v[1] == 0.0; // no curve and no margin
}

bool extraStringDampingNull(const std::vector<double>& v, const SimulationModel&)
{
    return v[0] == 1.0;
}

bool ambientTemperatureNull(const std::vector<double>& v, const SimulationModel&)
{
    return v[0] == 0.0;
}

bool frictionLawNull(const std::vector<double>& v, const SimulationModel& before)
{
    return before.preset.friction == kReplacementLaws[static_cast<std::size_t>(v[0])];
}

// A choice among `choices`: its range is the indices (0 .. choices - 1), so it cannot fall out of step with
// the list; rosin synth-data draws among the first drawMax + 1.
EffectParameter choiceParameter(std::string name, std::vector<std::string> choices, double drawMax,
                                std::string meaning)
{
    return {.name = std::move(name),
            .min = 0.0,
            .max = static_cast<double>(choices.size() - 1),
            .drawMin = 0.0,
            .drawMax = drawMax,
            .choices = std::move(choices),
            .meaning = std::move(meaning)};
}

std::vector<Effect> makeCatalog()
{
    // Fit ranges (min..max) are wide: a gap may call for more than synth-data hides. Draw ranges are
    // physically realistic strengths, strong enough to be seen through the measurement chain.
    const EffectParameter growth{.name = "growth",
                                 .min = 0.0,
                                 .max = 1.0,
                                 .drawMin = 0.1,
                                 .drawMax = 0.3,
                                 .meaning = "fractional static-limit gain per e-fold of hold time"};
    const EffectParameter onsetTime{.name = "onsetTime",
                                    .unit = "s",
                                    .min = 5e-4,
                                    .max = 0.05,
                                    .drawMin = 0.002,
                                    .drawMax = 0.010,
                                    .logarithmic = true,
                                    .meaning = "hold time at which ageing sets in"};
    // To 1, not further: the fit's grid (4 points) then lies at thirds, and a gain of about 0.3 has a point
    // of its own. Over 0..2 the first point off the null was 0.67, the grid's best for a hidden saturating
    // gain of 0.33 stayed at the null, and the fit never left it (tuning member 37; on member 33, a gain of
    // 0.28 reached only after a 25 ms onset, it still does not). The
    // literature's ageing is weaker still ([Notes §8.2]: beta_a 0.01-0.02, a gain of at most ~0.1 at 50 ms);
    // synth-data's draws reach 0.98.
    const EffectParameter gainAtReferenceHold{.name = "gainAfter50ms",
                                              .min = 0.0,
                                              .max = 1.0,
                                              .meaning = "fractional static-limit gain after a 50 ms hold"};
    // Signature families: an effect is named by what it does, not by one formula. Rosin's
    // own synth-data draws the first form (draw range 0..0), so its datasets stay as they were.
    const EffectParameter ageing =
        choiceParameter("ageingForm", {"logarithmic", "saturating"}, 0.0,
                        "growth without limit, ln(1 + t/tau), or towards one, 1 - exp(-t/tau)");
    const EffectParameter lossTerms = choiceParameter("lossTerms", {"all", "internal", "bending"}, 0.0,
                                                      "which terms of the loss law grow: all, the internal "
                                                      "friction (frequency-independent) or the bending term "
                                                      "(high partials)");
    // synth-data hides [Woodhouse-thermal]'s law, rod or bow, as it always did.
    const EffectParameter jumpCurve = choiceParameter("jumpCurve", {"rod", "bow", "none"}, 1.0,
                                                      "the jump curve h(v): rosin-coated rod (eq. 13) or bow "
                                                      "(eq. 12), or none (the baseline law keeps its curve)");
    // Drawn 0, so Rosin's own synth-data hides [Woodhouse-thermal]'s law as it always did.
    const EffectParameter firstSlipMargin{.name = "firstSlipMargin",
                                          .min = 0.0,
                                          .max = 1.0,
                                          .drawMin = 0.0,
                                          .drawMax = 0.0,
                                          .meaning = "fractional excess of the static limit at rest, "
                                                     "released by the first slip"};
    const EffectParameter creepResistance{.name = "creepResistance",
                                          .unit = "N s/m",
                                          .min = 5.0,
                                          .max = 2000.0,
                                          .drawMin = 40.0,
                                          .drawMax = 150.0,
                                          .logarithmic = true,
                                          .meaning = "dashpot in series with the sticking contact"};
    const EffectParameter lossScale{.name = "lossScale",
                                    .min = 1.0,
                                    .max = 10.0,
                                    .drawMin = 2.0,
                                    .drawMax = 4.0,
                                    .logarithmic = true,
                                    .meaning = "the loss law's terms (lossTerms) x this"};
    const EffectParameter ambientOffset{.name = "ambientOffset",
                                        .unit = "K",
                                        .min = -25.0,
                                        .max = 25.0,
                                        .drawMin = 8.0,
                                        .drawMax = 15.0,
                                        .signedDraw = true,
                                        .meaning = "rosin temperature at rest minus the stated ambient"};
    // Drawn among the three that are not the default baseline, so a hidden law always changes the model.
    EffectParameter replacementLaw =
        choiceParameter("replacementLaw", {std::begin(kReplacementLaws), std::end(kReplacementLaws)},
                        static_cast<double>(std::size(kReplacementLaws) - 1),
                        "the law of the source texts in the baseline's place: the plastic or viscous thermal "
                        "law, or the classical or reconstructed friction curve");
    replacementLaw.drawMin = 1.0;
    return {
        {"junction-growth",
         "limiting static friction grows with the time spent sticking (contact ageing)",
         "[Notes §8.2]",
         {growth, onsetTime, ageing},
         junctionGrowth,
         {gainAtReferenceHold, onsetTime, ageing},
         junctionGrowthFromSearch,
         junctionGrowthNull},
        {"breakaway-jump",
         "abrupt release at the first slip while the rosin is cold (modified thermal law)",
         "[Woodhouse-thermal] eqs. 6, 12, 13",
         {jumpCurve, firstSlipMargin},
         breakawayJump,
         {},
         nullptr,
         breakawayNull},
        {"hertz-contact",
         "contact area proportional to N^(2/3) instead of N",
         "[Notes §8.3]; [Galluzzo2017] Fig. 11",
         {},
         hertzContact},
        {"sticking-creep",
         "viscous-like creep during nominal sticking",
         "[Galluzzo2017] section 5.3",
         {creepResistance},
         stickingCreep},
        {"extra-string-damping",
         "string losses higher than the nominal loss law",
         "[Galluzzo2017] Table 1 (stopped-string bracket), Fig. 12c",
         {lossScale, lossTerms},
         extraStringDamping,
         {},
         nullptr,
         extraStringDampingNull},
        {"ambient-temperature",
         "the rosin starts warmer or colder than the rig's stated ambient temperature",
         "the three source texts: thermal laws calibrated at the rig's ambient",
         {ambientOffset},
         ambientTemperature,
         {},
         nullptr,
         ambientTemperatureNull},
        {"friction-law",
         "another friction law of the source texts in the baseline's place",
         "[Smith2000] eqs. 3, 4; [Galluzzo2017] eqs. 1, 2",
         {replacementLaw},
         frictionLawSwap,
         {},
         nullptr,
         frictionLawNull},
    };
}

std::string rangeText(const EffectParameter& p)
{
    if (!p.choices.empty())
        return "the index of one of " + std::to_string(p.choices.size()) + " choices";
    return physics::formatNumber(p.min) + ".." + physics::formatNumber(p.max) + (p.unit.empty() ? "" : " ") +
           p.unit;
}
} // namespace

const std::vector<Effect>& effectCatalog()
{
    static const std::vector<Effect> catalog = makeCatalog();
    return catalog;
}

std::vector<std::string> effectNames()
{
    std::vector<std::string> names;
    for (const auto& e : effectCatalog())
        names.push_back(e.name);
    return names;
}

const Effect* findEffect(const std::string& name)
{
    for (const auto& e : effectCatalog())
        if (e.name == name)
            return &e;
    return nullptr;
}

std::size_t effectIndex(const Effect& effect)
{
    return static_cast<std::size_t>(&effect - effectCatalog().data());
}

const std::vector<EffectParameter>& fitCoordinates(const Effect& effect)
{
    return effect.searchParameters.empty() ? effect.parameters : effect.searchParameters;
}

std::vector<double> parameterValues(const Effect& effect, const std::vector<double>& searchValues)
{
    return effect.fromSearch && !effect.searchParameters.empty() ? effect.fromSearch(searchValues)
                                                                 : searchValues;
}

bool isNull(const Effect& effect, const std::vector<double>& values, const SimulationModel& before)
{
    return effect.atNull != nullptr && effect.atNull(values, before);
}

void applyEffect(const Effect& effect, const std::vector<double>& values, SimulationModel& model)
{
    if (values.size() != effect.parameters.size())
        throw std::invalid_argument(effect.name + ": expected " + std::to_string(effect.parameters.size()) +
                                    " parameter value(s) but got " + std::to_string(values.size()));
    for (std::size_t i = 0; i < values.size(); ++i)
    {
        const auto& p = effect.parameters[i];
        const double v = values[i];
        const bool whole = p.choices.empty() || v == std::floor(v);
        if (!std::isfinite(v) || v < p.min || v > p.max || !whole)
            throw std::invalid_argument(effect.name + ": parameter " + p.name + ": expected " + rangeText(p) +
                                        " but got " + physics::formatNumber(v));
    }
    effect.change(model, values);
}

std::string formatParameterValue(const EffectParameter& p, double value)
{
    if (!p.choices.empty())
    {
        const auto i = static_cast<std::size_t>(value);
        return i < p.choices.size() ? p.choices[i] : physics::formatNumber(value);
    }
    return physics::formatNumber(value) + (p.unit.empty() ? "" : " " + p.unit);
}

std::string describeEffect(const Effect& effect, const std::vector<double>& values)
{
    std::string text = effect.name;
    for (std::size_t i = 0; i < effect.parameters.size() && i < values.size(); ++i)
        text += (i ? ", " : ": ") + effect.parameters[i].name + " = " +
                formatParameterValue(effect.parameters[i], values[i]);
    return text;
}

} // namespace rosin::discovery
