#include "lab/discovery/synth/SynthPlan.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "core/gesture/GestureLimits.h"

namespace rosin::discovery
{

namespace
{
double roundSignificant(double value, int digits)
{
    if (value == 0.0 || !std::isfinite(value))
        return value;
    const double scale =
        std::pow(10.0, digits - 1 - static_cast<int>(std::floor(std::log10(std::abs(value)))));
    return std::round(value * scale) / scale;
}

std::string padded(std::size_t value, std::size_t width)
{
    std::string text = std::to_string(value);
    return std::string(width > text.size() ? width - text.size() : 0, '0') + text;
}

std::size_t indexWidth(std::size_t count)
{
    return std::max<std::size_t>(2, std::to_string(count > 0 ? count - 1 : 0).size());
}

// Beta labels of `digits` decimals scaled to an integer (0.0899 -> "0899"), or empty if two collide.
std::vector<std::string> betaLabels(const std::vector<double>& betas, int digits)
{
    std::vector<std::string> labels;
    std::set<std::string> seen;
    for (double b : betas)
    {
        const auto scaled = static_cast<std::size_t>(std::llround(b * std::pow(10.0, digits)));
        labels.push_back(padded(scaled, static_cast<std::size_t>(digits)));
        if (!seen.insert(labels.back()).second)
            return {};
    }
    return labels;
}

std::vector<Channel> channelLayout(bool all)
{
    if (all)
        return {{"bridgeForce", "N"},
                {"frictionForce", "N"},
                {"bowPointVelocity", "m/s"},
                {"bowVelocity", "m/s"}};
    return {{"bridgeForce", "N"}, {"bowVelocity", "m/s"}};
}

// What a laboratory writes about its scan: the grid and the string, nothing about any model.
std::string describeScan(const scan::ScanSpec& s, const config::Preset& preset)
{
    const bool guettler = s.kind == scan::ScanKind::Guettler;
    std::string text = guettler ? "Guettler scan: " : "Schelleng scan: ";
    text += std::to_string(s.forces.size()) + " bow forces x ";
    text += guettler
                ? std::to_string(s.second.size()) + " accelerations (constant-acceleration starts from rest)"
                : std::to_string(s.betas.size()) + " bow positions at a steady " +
                      physics::formatNumber(s.second.front()) + " m/s";
    if (guettler)
        text += " at " + std::to_string(s.betas.size()) + " bow position(s)";
    return text + "; open string " + preset.string.name + " on the " + preset.body + " body; bowing machine";
}

Rig describeRig(const config::Preset& preset)
{
    Rig rig;
    rig.string = preset.string;
    rig.string.stoppedLossF = rig.string.lossF; // the dataset's string is bowed open
    rig.body = preset.body;
    rig.bow = {{"kind", "rod"}, {"material", "acrylic, rosin-coated"}, {"diameter", 0.013}};
    rig.ambientTemperature = kRigAmbientCelsius;
    return rig;
}

double jittered(double nominal, double share, SeededRandom& random)
{
    return nominal * (1.0 + share * std::clamp(random.normal(), -3.0, 3.0));
}
} // namespace

std::vector<double> drawEffectValues(const EffectRequest& request, std::uint64_t seed)
{
    const Effect& effect = *request.effect;
    SeededRandom random(seed, RandomStream::EffectValues, effectIndex(effect));
    std::vector<double> values;
    for (std::size_t i = 0; i < effect.parameters.size(); ++i)
    {
        const auto& p = effect.parameters[i];
        // Two draws per parameter whether or not its value is given, so fixing one value leaves the others.
        const double u = random.uniform();
        const bool negative = random.uniform() < 0.5;
        double v = 0.0;
        if (!p.choices.empty()) // uniform over the choices drawMin..drawMax
            v = std::min(p.drawMin + std::floor(u * (p.drawMax - p.drawMin + 1.0)), p.drawMax);
        else if (p.logarithmic)
            v = roundSignificant(p.drawMin * std::pow(p.drawMax / p.drawMin, u), 3);
        else
            v = roundSignificant(p.drawMin + (p.drawMax - p.drawMin) * u, 3);
        if (p.signedDraw && negative)
            v = -v;
        const bool given = i < request.fixed.size() && request.fixed[i];
        values.push_back(given ? *request.fixed[i] : v);
    }
    return values;
}

std::vector<std::string> trialIds(const scan::ScanSpec& s)
{
    std::vector<std::string> betas = betaLabels(s.betas, 4);
    if (betas.empty())
        betas = betaLabels(s.betas, 6);
    if (betas.empty())
        for (std::size_t i = 0; i < s.betas.size(); ++i)
            betas.push_back(std::string("i").append(padded(i, indexWidth(s.betas.size()))));
    const char* motion = s.kind == scan::ScanKind::Guettler ? "-a" : "-v";
    std::vector<std::string> ids;
    for (std::size_t cell = 0; cell < s.cellCount(); ++cell)
    {
        const auto c = scan::coordinatesOf(s, cell);
        ids.push_back("b" + betas[c.beta] + "-f" + padded(c.force, indexWidth(s.forces.size())) + motion +
                      padded(c.second, indexWidth(s.second.size())));
    }
    return ids;
}

SynthPlan planSynthData(const SynthSettings& settings)
{
    const scan::ScanSpec& s = settings.scan;
    SynthPlan plan;
    plan.seed = settings.seed;
    plan.generatorMember = settings.generatorMember;
    plan.presetName = settings.preset.name;
    plan.model.preset = settings.preset;
    for (const auto& request : settings.effects)
    {
        HiddenEffect hidden{request.effect, drawEffectValues(request, settings.seed)};
        applyEffect(*hidden.effect, hidden.values, plan.model);
        plan.effects.push_back(std::move(hidden));
    }

    Dataset& d = plan.dataset;
    d.description = describeScan(s, settings.preset);
    d.sampleRate = static_cast<int>(s.sampleRate);
    d.channels = channelLayout(settings.allChannels);
    d.rig = describeRig(settings.preset);
    d.sensor.highpassHz = kSensorHighpassHz;

    const auto ids = trialIds(s);
    const auto failed = chooseFailedTrials(s.cellCount(), settings.seed);
    const bool guettler = s.kind == scan::ScanKind::Guettler;
    for (std::size_t i = 0; i < s.cellCount(); ++i)
    {
        const scan::CellSettings cell = scan::cellSettings(s, i);
        Trial t;
        t.id = ids[i];
        t.file = "trials/" + t.id + ".wav";
        t.beta = cell.beta;
        t.bowForce = cell.force;
        t.gesture = guettler ? Gesture{ConstantAcceleration{cell.second}} : Gesture{Steady{cell.second}};
        t.valid = !std::binary_search(failed.begin(), failed.end(), i);

        SeededRandom random(settings.seed, RandomStream::Jitter, i);
        TrialSettings actual;
        actual.beta = cell.beta;
        actual.bowForce = jittered(cell.force, kForceJitter, random);
        const double motion = jittered(cell.second, kMotionJitter, random);
        actual.gesture = guettler ? Gesture{ConstantAcceleration{motion}} : Gesture{Steady{motion}};
        actual.seconds = s.trialSeconds;

        plan.faults.push_back(
            t.valid ? std::nullopt
                    : std::optional<TrialFault>(drawTrialFault(settings.seed, i, s.trialSeconds)));
        plan.actual.push_back(actual);
        d.trials.push_back(std::move(t));
    }
    return plan;
}

} // namespace rosin::discovery
