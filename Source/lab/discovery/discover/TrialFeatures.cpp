#include "lab/discovery/discover/TrialFeatures.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "core/analysis/ContactCycle.h"
#include "core/analysis/FirstSlip.h"
#include "core/analysis/GestureStart.h"
#include "core/analysis/HarmonicTilt.h"
#include "core/analysis/LineFit.h"
#include "core/analysis/PeriodEstimate.h"
#include "core/analysis/RegimeClassifier.h"
#include "core/analysis/SlipOnsets.h"
#include "core/analysis/TransientLength.h"

namespace rosin::discovery
{

namespace
{
constexpr double kTransientCap = 20.0;
constexpr double kCreepPoint = 0.6;    ///< read the rise at this share of t1
constexpr double kCreepWindow = 0.05;  ///< averaged over +- this share of t1
constexpr double kTiltShare = 0.4;     ///< harmonic tilt over the last 40 % of a trial
constexpr double kRegimeSettle = 20.0; ///< periods after the first slip before the regime is read
constexpr double kTiltSettle = 2.0;    ///< periods after t_H before the tilt is read

std::optional<double> tilt(const std::vector<double>& force, std::size_t from, const FeatureContext& c)
{
    analysis::HarmonicTiltOptions o;
    o.sampleRate = c.sampleRate;
    o.fundamentalHz = 1.0 / c.periodSeconds;
    return analysis::harmonicTiltDb(force, from, force.size(), o);
}

// The rise's curvature: the force at 0.6 t1 against the parabola F(t1) (t/t1)^2, with t counted from the
// stroke's start t0 (GestureStart; 0 where it is not known).
std::optional<double> creepIndex(const std::vector<double>& force, const analysis::FirstSlip& slip,
                                 const FeatureContext& c, double t0)
{
    const std::vector<double> x =
        c.highpassHz > 0.0 ? analysis::undoFirstOrderHighPass(force, c.highpassHz, c.sampleRate) : force;
    const double t1 = slip.firstSlipTime - t0;
    if (!(t1 > 0.0))
        return std::nullopt;
    const auto from =
        static_cast<std::size_t>(std::max(0.0, (t0 + (kCreepPoint - kCreepWindow) * t1) * c.sampleRate));
    const auto to =
        static_cast<std::size_t>(std::max(0.0, (t0 + (kCreepPoint + kCreepWindow) * t1) * c.sampleRate));
    if (to <= from + 2 || to >= x.size() || !(slip.forceAtSlip > 0.0))
        return std::nullopt;
    double sum = 0.0;
    for (std::size_t k = from; k <= to; ++k)
        sum += x[k];
    const double mean = sum / static_cast<double>(to - from + 1);
    // The index compares a rising pre-slip force with its parabola; where the force at 0.6 t1 is not
    // between 0 and the force at the slip (an early partial slip, a slip found after the force had
    // already fallen: seen at the lowest forces in both Rosin's and an independent model), there is no
    // rise to compare, and the index (below -1.78) would be a number without a meaning.
    if (!(mean > 0.0 && mean < slip.forceAtSlip))
        return std::nullopt;
    return 1.0 - mean / (kCreepPoint * kCreepPoint * slip.forceAtSlip);
}
// When the stroke started in the record, s: from the recorded bow velocity where it tells (an acquisition's
// start latency differs from trial to trial), else the record's time zero.
double strokeStart(const FeatureContext& c, const ContactSignals& contact)
{
    const auto* a = std::get_if<ConstantAcceleration>(&c.gesture);
    if (!a || !contact.bowVelocity)
        return 0.0;
    analysis::GestureStartOptions o;
    o.sampleRate = c.sampleRate;
    o.acceleration = a->acceleration;
    o.noiseRms = c.noiseRms;
    return analysis::gestureStartFromBowVelocity(*contact.bowVelocity, o).value_or(0.0);
}

// The bow's velocity over the trial: recorded, or the gesture's nominal one.
std::vector<double> bowVelocityOf(std::size_t frames, const FeatureContext& c, const ContactSignals& contact)
{
    if (contact.bowVelocity)
        return *contact.bowVelocity;
    std::vector<double> v(frames, 0.0);
    for (std::size_t k = 0; k < frames; ++k)
    {
        if (const auto* a = std::get_if<ConstantAcceleration>(&c.gesture))
            v[k] = a->acceleration * static_cast<double>(k) / c.sampleRate;
        else if (const auto* s = std::get_if<Steady>(&c.gesture))
            v[k] = s->speed;
    }
    return v;
}

// The Helmholtz period's flattening in cents over [from, end of the force), to a fraction of a sample
// (analysis::refinedPeriod near the classifier's whole-sample period).
std::optional<double> pitchCents(const std::vector<double>& force, std::size_t from,
                                 const analysis::RegimeAnalysis& r, double periodSamples)
{
    const auto period = analysis::refinedPeriod(force, from, force.size(), r.measuredPeriod);
    if (!period)
        return std::nullopt;
    return 1200.0 * std::log2(periodSamples / *period);
}

// The bridge force's rms about its linear trend over [from, end) against the ideal Helmholtz sawtooth's for
// the window's mean bow speed (TrialFeatures.h), dB.
std::optional<double> steadyLevel(const std::vector<double>& force, std::size_t from, const FeatureContext& c,
                                  const ContactSignals& contact)
{
    const std::size_t end = force.size();
    if (!(c.impedance > 0.0) || end < from + 16)
        return std::nullopt;
    const std::vector<double> vb = bowVelocityOf(end, c, contact);
    const analysis::LineFit trend = analysis::fitLine(force, from, end);
    double ss = 0.0, sv = 0.0;
    for (std::size_t k = from; k < end; ++k)
    {
        const double r = force[k] - trend.at(static_cast<double>(k));
        ss += r * r;
        sv += vb[k];
    }
    const double n = static_cast<double>(end - from), meanSpeed = sv / n;
    const double ideal = 2.0 * c.impedance * std::abs(meanSpeed) / (c.beta * std::sqrt(12.0));
    if (!(ideal > 0.0) || !(ss > 0.0))
        return std::nullopt;
    return 10.0 * std::log10(ss / n / (ideal * ideal));
}

// Slip fraction and loop area over the Helmholtz window [from, end), where the contact was recorded.
void addContactFeatures(TrialFeatures& f, std::size_t from, std::size_t frames, const FeatureContext& c,
                        const ContactSignals& contact)
{
    if (!contact.bowPointVelocity)
        return;
    const std::vector<double> vb = bowVelocityOf(frames, c, contact);
    f[kSlipFraction] = analysis::slipFraction(*contact.bowPointVelocity, vb, from, frames);
    if (contact.frictionForce)
        f[kLoopArea] = analysis::normalisedLoopArea(*contact.bowPointVelocity, vb, *contact.frictionForce,
                                                    c.bowForce, from, frames, c.periodSeconds * c.sampleRate);
}
} // namespace

const char* featureName(std::size_t feature) noexcept
{
    static constexpr const char* names[] = {"staticFriction",   "jump",       "creep",        "firstSlipTime",
                                            "transientPeriods", "pitchCents", "harmonicTilt", "steadyLevel",
                                            "slipFraction",     "loopArea",   "regime"};
    static_assert(std::size(names) == kFeatureCount, "one name per feature");
    return feature < kFeatureCount ? names[feature] : "?";
}

const char* featureUnit(std::size_t feature) noexcept
{
    static constexpr const char* units[] = {"", "", "", "s", "periods", "cents", "dB", "dB", "", "", ""};
    static_assert(std::size(units) == kFeatureCount, "one unit per feature");
    return feature < kFeatureCount ? units[feature] : "";
}

double featureResolution(std::size_t feature, double sampleRate) noexcept
{
    switch (feature)
    {
    case kStaticFriction:
    case kJump:
        return 0.002;
    case kCreep:
        return 0.005;
    case kFirstSlipTime:
        return std::max(1e-4, 2.0 / sampleRate);
    case kTransientPeriods:
        return 0.5;
    case kHarmonicTilt:
    case kSteadyLevel:
        return 0.2;
    case kSlipFraction:
        return 0.005;
    case kLoopArea:
        return 0.002;
    default:
        return 1.0;
    }
}

bool describesHelmholtzMotion(std::size_t feature) noexcept
{
    return feature == kPitchCents || feature == kHarmonicTilt || feature == kSlipFraction ||
           feature == kLoopArea;
}

bool isCategorical(std::size_t feature) noexcept
{
    return feature == kRegime;
}

FeatureContext featureContext(const Dataset& dataset, const Trial& trial)
{
    FeatureContext c;
    c.sampleRate = dataset.sampleRate;
    c.beta = trial.beta;
    c.bowForce = trial.bowForce;
    c.gesture = trial.gesture;
    c.periodSeconds = 1.0 / dataset.rig.string.fundamental();
    c.highpassHz = dataset.sensor.highpassHz.value_or(0.0);
    c.noiseRms = dataset.sensor.noiseRms.value_or(0.0);
    c.impedance = std::sqrt(dataset.rig.string.tension * dataset.rig.string.massPerLength);
    return c;
}

TrialFeatures computeTrialFeatures(const std::vector<double>& force, const FeatureContext& c,
                                   const ContactSignals& contact)
{
    TrialFeatures f;
    const double periodSamples = c.periodSeconds * c.sampleRate;
    analysis::ForceOnsetOptions onsetOptions;
    onsetOptions.noiseRms = c.noiseRms;
    if (std::holds_alternative<ConstantAcceleration>(c.gesture))
    {
        analysis::FirstSlipOptions o;
        o.sampleRate = c.sampleRate;
        o.beta = c.beta;
        o.bowForce = c.bowForce;
        o.periodSeconds = c.periodSeconds;
        o.highPassCutoffHz = c.highpassHz;
        const analysis::FirstSlip slip = analysis::firstSlipFromBridgeForce(force, o);
        if (slip.found)
        {
            f[kStaticFriction] = slip.muStatic;
            f[kJump] = slip.jump;
            const double t0 = strokeStart(c, contact);
            f[kFirstSlipTime] = slip.firstSlipTime - t0;
            f[kCreep] = creepIndex(force, slip, c, t0);
            const auto onsets = analysis::slipOnsetsFromBridgeForce(force, periodSamples, onsetOptions);
            analysis::TransientOptions t;
            t.capPeriods = kTransientCap;
            t.windowEnd = force.size();
            const analysis::TransientLength tr = analysis::measureTransient(onsets, periodSamples, t);
            const double settledRegime = slip.firstSlipTime * c.sampleRate + kRegimeSettle * periodSamples;
            const auto regimeFrom = static_cast<std::size_t>(
                std::max(settledRegime, (1.0 - kTiltShare) * static_cast<double>(force.size())));
            if (regimeFrom + 4 * static_cast<std::size_t>(periodSamples) < force.size())
            {
                const analysis::RegimeAnalysis r = analysis::classifyFromForceOnsets(
                    onsets, force, periodSamples, analysis::AnalysisWindow{regimeFrom, 0});
                f[kRegime] = static_cast<double>(r.regime);
                if (r.regime == analysis::Regime::Helmholtz)
                    f[kPitchCents] = pitchCents(force, regimeFrom, r, periodSamples);
            }
            if (tr.slipped && (tr.periods || !tr.insufficientData))
                f[kTransientPeriods] = std::min(tr.periods.value_or(kTransientCap), kTransientCap);
            if (tr.helmholtzStart)
            {
                const double settled = static_cast<double>(*tr.helmholtzStart) + kTiltSettle * periodSamples;
                const double tail = (1.0 - kTiltShare) * static_cast<double>(force.size());
                const auto from = static_cast<std::size_t>(std::max(settled, tail));
                f[kHarmonicTilt] = tilt(force, from, c);
                addContactFeatures(f, from, force.size(), c, contact);
            }
        }
    }
    else if (std::holds_alternative<Steady>(c.gesture))
    {
        const analysis::RegimeAnalysis r = analysis::classifyFromBridgeForce(
            force, periodSamples, analysis::AnalysisWindow{force.size() / 2, 0}, onsetOptions);
        f[kRegime] = static_cast<double>(r.regime);
        f[kSteadyLevel] = steadyLevel(force, force.size() / 2, c, contact);
        if (r.regime == analysis::Regime::Helmholtz)
        {
            f[kPitchCents] = pitchCents(force, force.size() / 2, r, periodSamples);
            f[kHarmonicTilt] = tilt(force, force.size() / 2, c);
            addContactFeatures(f, force.size() / 2, force.size(), c, contact);
        }
    }
    return f;
}

} // namespace rosin::discovery
