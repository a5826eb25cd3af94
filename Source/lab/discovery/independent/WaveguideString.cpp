#include "lab/discovery/independent/WaveguideString.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace rosin::discovery
{

OnePoleLoss segmentLoss(const LossLaw& eta, double tau, double referenceHz, double sampleRate,
                        double harmonic)
{
    const double f2 = std::min(harmonic * referenceHz, sampleRate / 5.0);
    return OnePoleLoss(eta, tau, referenceHz, std::max(f2, 1.5 * referenceHz), sampleRate);
}

WaveguideSegment::WaveguideSegment(double roundTripSamples, const LossLaw& eta, double referenceHz,
                                   double sampleRate, DispersionAllpass dispersion, double lossFitHarmonic)
    : out_(roundTripSamples + 8), back_(roundTripSamples + 8), dispersion_(std::move(dispersion))
{
    // The loss is fitted at the reference (the string's fundamental, where decay is measured) and at its
    // 36th partial (not above fs/5, where the one-pole has run out of shape): the middle of the band where
    // the rounding of the Helmholtz corner shows (harmonics 25-60, analysis::HarmonicTilt). Fitted at the 6th
    // instead, the one-pole lost too little there: its Helmholtz motion came out 2 dB brighter than the loss
    // law makes it, a difference of numerics that would read as a missing effect.
    const double tau = roundTripSamples / sampleRate;
    if (eta)
        loss_ = segmentLoss(eta, tau, referenceHz, sampleRate, lossFitHarmonic);
    // The filters' delay at the reference comes out of the two lines, shared evenly (the dispersion cascade
    // may take half of the segment). A segment shorter than the line's minimum (torsion near the bridge at
    // small beta) runs slightly long.
    const double filters = loss_.phaseDelay(referenceHz) + dispersion_.phaseDelay(referenceHz);
    d1_ = std::max(1.0, std::floor(0.5 * (roundTripSamples - filters)));
    d2_ = std::max(0.0, roundTripSamples - d1_ - filters);
    built_ = d1_ + d2_ + filters;
}

WaveguideString::WaveguideString(const WaveguideSettings& s)
    : z0_(std::sqrt(s.tension * s.massPerLength)), zt_(s.torsionalImpedance),
      f0_(std::sqrt(s.tension / s.massPerLength) / (2.0 * s.length)), torsion_(s.torsion),
      body_(s.body, s.sampleRate)
{
    const double c = std::sqrt(s.tension / s.massPerLength);
    const double fs = s.sampleRate;
    // The loop's dispersion cascade, shared between the two sides by length (equal sections), so waves
    // between bow and bridge disperse too. The loop stays tuned to c/(2L) at the fundamental (stiffness
    // would raise it by B/2: 0.05 cents).
    const double B = std::pow(std::numbers::pi, 2) * s.bendingStiffness / (s.tension * s.length * s.length);
    std::function<double(double)> lossDelay;
    if (s.transverseLoss)
    {
        const double loop = 2.0 * s.length / c;
        const OnePoleLoss bridgeLoss =
            segmentLoss(s.transverseLoss, s.beta * loop, f0_, fs, s.lossFitHarmonic);
        const OnePoleLoss nutLoss =
            segmentLoss(s.transverseLoss, (1.0 - s.beta) * loop, f0_, fs, s.lossFitHarmonic);
        lossDelay = [bridgeLoss, nutLoss](double f)
        { return bridgeLoss.phaseDelay(f) + nutLoss.phaseDelay(f); };
    }
    const DispersionDesign design =
        designDispersion(2.0 * s.length / c * fs, f0_, B, fs, lossDelay, s.dispersionFitTopHz);
    const int bridgeSections = static_cast<int>(std::lround(s.beta * design.sections));
    bridge_ = WaveguideSegment(2.0 * s.beta * s.length / c * fs, s.transverseLoss, f0_, fs,
                               DispersionAllpass(design, bridgeSections, fs), s.lossFitHarmonic);
    nut_ =
        WaveguideSegment(2.0 * (1.0 - s.beta) * s.length / c * fs, s.transverseLoss, f0_, fs,
                         DispersionAllpass(design, design.sections - bridgeSections, fs), s.lossFitHarmonic);
    admittance_ = 1.0 / (2.0 * z0_);
    if (torsion_)
    {
        const double ct = s.torsionalWaveSpeed, q = s.torsionalQ;
        const LossLaw eta = [q](double) { return 1.0 / q; };
        const double ft = ct / (2.0 * s.length);
        torsionBridge_ = WaveguideSegment(2.0 * s.beta * s.length / ct * fs, eta, ft, fs);
        torsionNut_ = WaveguideSegment(2.0 * (1.0 - s.beta) * s.length / ct * fs, eta, ft, fs);
        admittance_ += 1.0 / (2.0 * zt_);
    }
}

double WaveguideString::reflectAtBridge(double incident) noexcept
{
    if (body_.rigid())
    {
        bridgeForce_ = 2.0 * z0_ * incident;
        return -incident;
    }
    // [Notes] eq. (5.1a): string velocity at the bridge = bridge velocity = history + y0 F.
    const double y = body_.directAdmittance() * z0_;
    const double reflected = (body_.historyVelocity() + (y - 1.0) * incident) / (1.0 + y);
    bridgeForce_ = z0_ * (incident - reflected);
    body_.advance(bridgeForce_);
    return reflected;
}

double WaveguideString::beginStep(std::size_t n) noexcept
{
    bridge_.reflect(n, reflectAtBridge(bridge_.incidentAtEnd(n)));
    nut_.reflect(n, -nut_.incidentAtEnd(n));
    arrivingBridge_ = bridge_.arriving(n);
    arrivingNut_ = nut_.arriving(n);
    double vh = arrivingBridge_ + arrivingNut_;
    if (torsion_)
    {
        torsionBridge_.reflect(n, -torsionBridge_.incidentAtEnd(n));
        torsionNut_.reflect(n, -torsionNut_.incidentAtEnd(n));
        tArrivingBridge_ = torsionBridge_.arriving(n);
        tArrivingNut_ = torsionNut_.arriving(n);
        vh += tArrivingBridge_ + tArrivingNut_;
    }
    return vh;
}

void WaveguideString::finishStep(std::size_t n, double f) noexcept
{
    // A wave passes the bow point unchanged, plus what the force radiates each way.
    const double radiated = f / (2.0 * z0_);
    bridge_.send(n, arrivingNut_ + radiated);
    nut_.send(n, arrivingBridge_ + radiated);
    if (torsion_)
    {
        const double twist = f / (2.0 * zt_);
        torsionBridge_.send(n, tArrivingNut_ + twist);
        torsionNut_.send(n, tArrivingBridge_ + twist);
    }
}

} // namespace rosin::discovery
