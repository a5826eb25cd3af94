#include "instrument/engine/Engine.h"

#include <cmath>
#include <iostream>
#include <numbers>

namespace rosin::engine
{

// For Schelleng's F_min = Z0^2 v_b G / (2 beta^2 (mu_s - mu_d)): the body's mean real admittance over the
// string's first ten harmonics, plus the string's own damping of its fundamental expressed as the bridge
// conductance that would lose as much per period (reflection 1 - 2 Z0 G = exp(-pi eta) => G = pi eta / (2
// Z0)). A simple estimate, for display.
double schellengConductance(const physics::InstrumentConfig& config, std::size_t i)
{
    const physics::StringParameters& string = config.strings[i];
    const double f0 = string.fundamental();
    double body = 0.0;
    constexpr int kPoints = 32;
    for (int k = 0; k < kPoints; ++k)
        body += config.body.admittance(f0 * std::pow(10.0, k / (kPoints - 1.0))).real();
    body = std::max(0.0, body / kPoints);
    const double z0 = string.impedance();
    const double eta = string.lossFactor(1, string.length, false);
    return body + (z0 > 0.0 ? std::numbers::pi * eta / (2.0 * z0) : 0.0);
}

player::PlayableBand playableBand(const physics::InstrumentConfig& config, std::size_t i,
                                  const physics::FrictionLimits& friction)
{
    player::PlayableBand band;
    band.Z0 = config.strings[i].impedance();
    band.conductance = schellengConductance(config, i);
    band.muStatic = friction.muStatic;
    band.muDynamic = friction.muDynamic;
    band.periodTimesZ0 = band.Z0 / config.strings[i].fundamental();
    band.lowerEdge = player::kMeasuredLowerEdge;
    band.upperEdge = player::kMeasuredUpperEdge;
    return band;
}

double bowForceShare(double impedance)
{
    static const double reference = physics::stringFromCatalogue(kBowForceReferenceString).impedance();
    return impedance / reference;
}

std::unique_ptr<Engine> buildEngine(const InstrumentKey& key, const ProgramExtras& extras,
                                    int programGeneration, long serial, double sampleRate)
{
    auto engine = std::make_unique<Engine>();
    engine->key = key;
    engine->programGeneration = programGeneration;
    engine->sampleRate = sampleRate;
    engine->serial = serial;
    physics::InstrumentConfig config;
    try
    {
        config = buildInstrumentConfig(key, extras);
    }
    catch (const std::exception& e)
    {
        std::cerr << "rosin: program ignored: " << e.what() << "\n";
        config = buildInstrumentConfig(key, ProgramExtras{});
    }
    engine->instrument.prepare(config, sampleRate);
    const auto friction = physics::frictionLimits(config.friction, config.contact, sampleRate);
    for (int i = 0;
         i < engine->instrument.stringCount() && i < static_cast<int>(engine->openFrequencies.size()); ++i)
    {
        const auto k = static_cast<std::size_t>(i);
        engine->openFrequencies[k] = engine->instrument.openFrequency(i);
        engine->impedances[k] = engine->instrument.config().strings[k].impedance();
        engine->bridgeConductances[k] = schellengConductance(engine->instrument.config(), k);
        engine->forceShares[k] = bowForceShare(engine->impedances[k]);
        engine->bands[k] = playableBand(engine->instrument.config(), k, friction);
    }
    return engine;
}

} // namespace rosin::engine
