#include "lab/discovery/NuisanceParameters.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rosin::discovery
{

namespace
{
NuisanceParameter factor(const char* name, double NuisanceValues::*value, double min, double max,
                         const char* meaning)
{
    return {EffectParameter{.name = name, .min = min, .max = max, .logarithmic = true, .meaning = meaning},
            value};
}

NuisanceParameter chain(NuisanceParameter p)
{
    p.measurementChain = true;
    p.startsCalibrated = true;
    return p;
}

NuisanceParameter tuning(NuisanceParameter p)
{
    p.startsCalibrated = true;
    return p;
}

std::vector<NuisanceParameter> makeParameters()
{
    return {
        factor("contactRadius", &NuisanceValues::contactRadius, 0.87, 1.15, "contact radius x this"),
        factor("rosinConductivity", &NuisanceValues::rosinConductivity, 0.83, 1.2,
               "thermal conductivity of the rosin x this"),
        factor("rosinHeatCapacity", &NuisanceValues::rosinHeatCapacity, 0.83, 1.2,
               "volumetric heat capacity of the rosin x this"),
        tuning(factor("tension", &NuisanceValues::tension, 0.98, 1.02, "string tension x this")),
        factor("stringLoss", &NuisanceValues::stringLoss, 0.83, 1.2, "every transverse loss factor x this"),
        chain(
            factor("sensorGain", &NuisanceValues::sensorGain, 0.97, 1.03, "force gauge sensitivity x this")),
        {EffectParameter{.name = "sensorBandwidth",
                         .min = 0.2,
                         .max = 0.5,
                         .logarithmic = true,
                         .meaning = "the chain's low-pass corner / sample rate (0.5: none)"},
         &NuisanceValues::sensorBandwidth, true, true},
        {EffectParameter{.name = "sensorDelay",
                         .unit = "s",
                         .min = 0.0,
                         .max = 0.0015,
                         .meaning = "how late the force channels are after the gesture"},
         &NuisanceValues::sensorDelay, true, true},
    };
}
} // namespace

const std::vector<NuisanceParameter>& nuisanceParameters()
{
    static const std::vector<NuisanceParameter> parameters = makeParameters();
    return parameters;
}

bool isMeasurementChain(const EffectParameter& prior) noexcept
{
    for (const auto& p : nuisanceParameters())
        if (&p.prior == &prior)
            return p.measurementChain;
    return false;
}

double sensorLowpassHz(const NuisanceValues& values, double sampleRate) noexcept
{
    // Within 1 % of Nyquist the filter would do nothing but ring: treat it as absent.
    return values.sensorBandwidth >= 0.495 ? 0.0 : values.sensorBandwidth * sampleRate;
}

std::size_t sensorDelaySamples(const NuisanceValues& values, double sampleRate) noexcept
{
    return static_cast<std::size_t>(std::max(0.0, std::round(values.sensorDelay * sampleRate)));
}

std::string describeNuisance(const NuisanceValues& values)
{
    std::string text;
    for (const auto& p : nuisanceParameters())
    {
        const double v = values.*p.value;
        if (v == p.nominal())
            continue;
        char part[80];
        if (p.value == &NuisanceValues::sensorDelay)
            std::snprintf(part, sizeof(part), "%s %.3g ms", p.prior.name.c_str(), 1e3 * v);
        else if (p.value == &NuisanceValues::sensorBandwidth)
            std::snprintf(part, sizeof(part), "%s %.3g of the sample rate", p.prior.name.c_str(), v);
        else
            std::snprintf(part, sizeof(part), "%s x%.3g", p.prior.name.c_str(), v);
        text += (text.empty() ? "" : ", ") + std::string(part);
    }
    return text.empty() ? "nominal" : text;
}

} // namespace rosin::discovery
