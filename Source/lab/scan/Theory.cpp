#include "lab/scan/Theory.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/physics/body/BodyParameters.h"

namespace rosin::scan
{

namespace
{
constexpr double kPi = std::numbers::pi;
constexpr int kHarmonics = 400; ///< [Notes §6.2] evaluates (6.5) with 400 harmonics
constexpr int kTimeSteps = 2000;
} // namespace

FrictionLimits frictionLimits(const ModelSpec& model, double sampleRate)
{
    return physics::frictionLimits(physics::frictionModelFromName(model.friction), model.contact, sampleRate);
}

double fminCoefficient(const std::function<std::complex<double>(double)>& admittance, double f0, double Z0,
                       double vb, double dmu)
{
    std::vector<std::complex<double>> y(kHarmonics + 1);
    double constant = 0.0;
    for (int n = 1; n <= kHarmonics; ++n)
    {
        y[static_cast<std::size_t>(n)] = admittance(n * f0) / static_cast<double>(n * n);
        constant += y[static_cast<std::size_t>(n)].real();
    }
    double worst = -1e300;
    for (int k = 0; k < kTimeSteps; ++k)
    {
        const double phase = 2.0 * kPi * k / kTimeSteps; // w0 t over one period
        double s = 0.0;
        for (int n = 1; n <= kHarmonics; ++n)
            s += (n % 2 == 0 ? 1.0 : -1.0) *
                 (y[static_cast<std::size_t>(n)] * std::polar(1.0, n * phase)).real();
        worst = std::max(worst, constant - s);
    }
    return 2.0 * vb * Z0 * Z0 / (kPi * kPi * dmu) * worst;
}

double stringLossConductance(const physics::StringParameters& string, int n)
{
    return kPi * n * string.lossFactor(n, string.length, false) / (2.0 * string.impedance());
}

Theory scanTheory(const ScanSpec& spec)
{
    Theory t;
    const auto& s = spec.model.string;
    t.Z0 = s.impedance();
    t.friction = frictionLimits(spec.model, spec.sampleRate);
    t.periodSeconds = 1.0 / s.fundamental();
    const double dmu = t.friction.muStatic - t.friction.muDynamic;
    // Schelleng's lines at the scan's bow speed; a Guettler scan reports R alone, which does not depend on
    // it.
    const double vb = spec.kind == ScanKind::Schelleng ? spec.second.front() : 1.0;
    t.fmaxCoefficient = 2.0 * t.Z0 * vb / dmu;
    const physics::BodyParameters body = physics::bodyByName(spec.model.body);
    const double f0 = s.fundamental();
    t.fminTotalCoefficient = fminCoefficient(
        [&](double f)
        {
            const int n = std::max(1, static_cast<int>(std::lround(f / f0)));
            return (body.rigid() ? std::complex<double>{} : body.admittance(f)) + stringLossConductance(s, n);
        },
        f0, t.Z0, vb, dmu);
    if (!body.rigid())
    {
        t.fminCoefficient =
            fminCoefficient([&](double f) { return body.admittance(f); }, s.fundamental(), t.Z0, vb, dmu);
        if (t.fminCoefficient > 0.0)
            t.bridgeResistance = t.Z0 * t.Z0 * vb / (2.0 * t.fminCoefficient * dmu);
    }
    if (spec.kind == ScanKind::Schelleng)
        return t;
    for (const double beta : spec.betas)
        t.wedge.push_back(
            guettlerWedge(beta, t.friction.muStatic, t.friction.muDynamic, t.periodSeconds * t.Z0));
    return t;
}

} // namespace rosin::scan
