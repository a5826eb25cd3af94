// Offline rig runs and the modal-mass calibration (RigCalibration.h).
#include "core/physics/rig/RigCalibration.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/physics/friction/CurveFrictionLaw.h"
#include "core/physics/laws/FrictionLawFactory.h"
#include "core/physics/numeric/BracketedRoot.h"
#include "core/physics/rig/CantileverContact.h"
#include "core/physics/thermal/RosinMaterial.h"

namespace rosin::physics
{

namespace
{
// Stick-slip settles within a few cycles; the second half of a 1 s run is steady for every law tried.
constexpr double kCalibrationSeconds = 1.0;
constexpr double kSettleSeconds = 0.5;
// The plastic law's period shortens over the first ~20 cycles as the wedge warms: judge it over 1-2 s.
constexpr double kThermalSeconds = 2.0;
constexpr double kThermalSettleSeconds = 1.0;

std::string bracketError(const char* what, double targetHz, double flo, double lo, double fhi, double hi)
{
    return std::string(what) + ": " + std::to_string(targetHz) + " Hz is not between " + std::to_string(flo) +
           " Hz (" + std::to_string(lo) + ") and " + std::to_string(fhi) + " Hz (" + std::to_string(hi) + ")";
}
} // namespace

RigRun runRig(const OscillatorRigParameters& rig, std::unique_ptr<FrictionLaw> law, double sampleRate,
              double normalForce, double rodSpeed, double seconds)
{
    OscillatorRig r;
    r.prepare(rig, std::move(law), sampleRate);
    RigRun run{sampleRate, {}};
    const auto n = static_cast<std::size_t>(seconds * sampleRate);
    run.samples.reserve(n);
    for (std::size_t k = 0; k < n; ++k)
        run.samples.push_back(r.step({normalForce, rodSpeed}));
    return run;
}

std::vector<double> slipOnsetTimes(const RigRun& run, double fromSeconds)
{
    std::vector<double> onsets;
    for (std::size_t k = 1; k < run.samples.size(); ++k)
    {
        const double t = static_cast<double>(k) / run.sampleRate;
        if (t >= fromSeconds && run.samples[k - 1].sticking && !run.samples[k].sticking)
            onsets.push_back(t);
    }
    return onsets;
}

double stickSlipFrequency(const RigRun& run, double fromSeconds)
{
    const auto onsets = slipOnsetTimes(run, fromSeconds);
    if (onsets.size() < 3)
        return 0.0;
    return static_cast<double>(onsets.size() - 1) / (onsets.back() - onsets.front());
}

double calibrateModalMass(const OscillatorRigParameters& rig, double targetHz, double sampleRate,
                          double lowKg, double highKg)
{
    auto frequencyAt = [&](double mass)
    {
        OscillatorRigParameters p = rig;
        p.modalMass = mass;
        const RigRun run =
            runRig(p, std::make_unique<ClassicalFrictionLaw>(ClassicalCurve{}, "classical"), sampleRate,
                   CantileverLoad::normalForce, CantileverLoad::rodSpeed, kCalibrationSeconds);
        return stickSlipFrequency(run, kSettleSeconds);
    };
    double lo = lowKg, hi = highKg;
    const double flo = frequencyAt(lo), fhi = frequencyAt(hi);
    if (!(flo < targetHz && fhi > targetHz))
        throw std::runtime_error(bracketError("calibrateModalMass (kg)", targetHz, flo, lo, fhi, hi));
    // The measured frequency is quantised by the sample period, so 30 halvings of the log range are plenty.
    return bisectGeometric([&](double mass) { return frequencyAt(mass) < targetHz; }, lo, hi, 1e-5, 30);
}

double calibrateRosinHeatCapacity(double targetHz, double sampleRate, double low, double high)
{
    auto frequencyAt = [&](double factor)
    {
        ContactParameters contact = cantileverContact();
        contact.materials = withRosin(contact.materials, rosinWithHeatCapacityFactor(factor));
        const RigRun run =
            runRig(OscillatorRigParameters{}, makeFrictionLaw(FrictionModel::Plastic, contact), sampleRate,
                   CantileverLoad::normalForce, CantileverLoad::rodSpeed, kThermalSeconds);
        return stickSlipFrequency(run, kThermalSettleSeconds);
    };
    const double flo = frequencyAt(low), fhi = frequencyAt(high);
    if (!(flo > targetHz && fhi < targetHz))
        throw std::runtime_error(
            bracketError("calibrateRosinHeatCapacity (x handbook rho c)", targetHz, flo, low, fhi, high));
    return bisectGeometric([&](double factor) { return frequencyAt(factor) > targetHz; }, low, high, 1e-3,
                           30);
}

} // namespace rosin::physics
