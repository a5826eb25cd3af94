#pragma once
// The independent generator's string: a digital waveguide in the manner of McIntyre, Schumacher and Woodhouse
// [MSW1983]
// ([Notes §1.1-1.2]), not Rosin's modal sum. The bow divides the string into a bridge-side segment (beta L)
// and a nut-side segment ((1 - beta) L); on each, velocity waves run to the far end and back through a
// fractional delay line with the segment's share of the string's losses (LossFilter). The bow point sees
// v = v_h + f (1/(2 Z0) + 1/(2 Zt)): the history v_h is the sum of the waves arriving now, and the friction
// force f sends f/(2 Z0) both ways (and f/(2 Zt) on the torsional pair, whose waves are surface-referred
// angular velocities, because the bow acts at the string's surface).
//
// Ends: the nut and both torsional ends reflect rigidly (-1); the bridge is rigid or a body (BodyResonators,
// [Notes] eq. 5.1a). The force on the bridge is Z0 (v_incident - v_reflected) ([Notes §5.1]).
#include <cstddef>

#include "lab/discovery/independent/BodyResonators.h"
#include "lab/discovery/independent/DispersionAllpass.h"
#include "lab/discovery/independent/FractionalDelay.h"
#include "lab/discovery/independent/LossFilter.h"

namespace rosin::discovery
{

struct WaveguideSettings
{
    double tension = 111.0;        ///< N
    double massPerLength = 2.7e-3; ///< kg/m
    double length = 0.6906;        ///< m
    double beta = 0.0899;
    LossLaw transverseLoss;        ///< eta(f) of transverse waves; empty: lossless
    double bendingStiffness = 0.0; ///< EI, N m^2: dispersion allpasses on both sides of the bow (0: none)
    bool torsion = true;
    double torsionalWaveSpeed = 758.0; ///< m/s
    double torsionalQ = 45.0;
    double torsionalImpedance = 1.8; ///< kg/s, surface-referred
    physics::BodyParameters body;    ///< no modes: rigid bridge
    double sampleRate = 88200.0;
    double lossFitHarmonic = 36.0;       ///< the loss filters' second fit frequency, x f0 (segmentLoss)
    double dispersionFitTopHz = 10000.0; ///< the dispersion cascade fits the partials below this
};

/// One side of the bow: a line to the far end (integer delay), the segment's loss, and a line back
/// (fractional delay, shortened by the loss filter's phase delay at referenceHz).
/// The loss filter of a segment whose round trip takes `tau` s: fitted at the reference (the string's
/// fundamental) and at its `harmonic`-th partial (36 by default).
OnePoleLoss segmentLoss(const LossLaw& eta, double tau, double referenceHz, double sampleRate,
                        double harmonic = 36.0);

class WaveguideSegment
{
  public:
    WaveguideSegment() = default;
    /// `dispersion`: the stiff string's allpass, placed in this segment (empty: none).
    WaveguideSegment(double roundTripSamples, const LossLaw& eta, double referenceHz, double sampleRate,
                     DispersionAllpass dispersion = {}, double lossFitHarmonic = 36.0);

    /// The wave reaching the far end at step n, after the segment's loss (and dispersion).
    double incidentAtEnd(std::size_t n) noexcept
    {
        return dispersion_.process(loss_.process(out_.read(n, d1_)));
    }
    void reflect(std::size_t n, double v) noexcept { back_.write(n, v); }
    /// The wave arriving at the bow at step n (after reflect(n, ...)).
    double arriving(std::size_t n) const noexcept { return back_.read(n, d2_); }
    void send(std::size_t n, double v) noexcept { out_.write(n, v); }
    /// The round trip as built (samples at referenceHz), which a very short segment may lengthen.
    double roundTrip() const noexcept { return built_; }

  private:
    FractionalDelay out_, back_;
    OnePoleLoss loss_;
    DispersionAllpass dispersion_;
    double d1_ = 1.0, d2_ = 1.0, built_ = 2.0;
};

class WaveguideString
{
  public:
    explicit WaveguideString(const WaveguideSettings& settings);

    /// Runs the ends of step n and returns the bow point's history velocity (surface, m/s).
    double beginStep(std::size_t n) noexcept;
    /// Sends the friction force f (N, on the string) of step n into the waves.
    void finishStep(std::size_t n, double f) noexcept;
    /// Bow point's velocity per newton of friction force (s/kg): 1/(2 Z0) (+ 1/(2 Zt)).
    double admittance() const noexcept { return admittance_; }
    /// Force of the string on the bridge at the last beginStep (N).
    double bridgeForce() const noexcept { return bridgeForce_; }
    double impedance() const noexcept { return z0_; }
    double fundamental() const noexcept { return f0_; }
    /// Round trips (samples) of the bridge-side and nut-side transverse segments, as built.
    double roundTrip() const noexcept { return bridge_.roundTrip() + nut_.roundTrip(); }

  private:
    double z0_, zt_, f0_, admittance_;
    bool torsion_;
    WaveguideSegment bridge_, nut_, torsionBridge_, torsionNut_;
    BodyResonators body_;
    double arrivingBridge_ = 0.0, arrivingNut_ = 0.0, tArrivingBridge_ = 0.0, tArrivingNut_ = 0.0;
    double bridgeForce_ = 0.0;
    double reflectAtBridge(double incident) noexcept;
};

} // namespace rosin::discovery
