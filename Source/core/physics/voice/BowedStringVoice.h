#pragma once
// One bowed string: transverse and torsional modes of a stiff string, a modal body at the bridge, and a
// friction law at the bow, advanced one sample at a time.
//
// Formulation ([Notes §1, §4.4, §5.1]; Resources/docs/physics.md, "The model"):
//  * string displacement y(x,t) = u(t)(1 - x/L) + sum_n q_n(t) sin(n pi x/L), bridge at x = 0, u the
//    bridge (body) displacement: the quasi-static term carries the moving bridge exactly;
//  * every mode is a second-order oscillator discretised by impulse invariance with a half-sample direct
//    term (ModalBank.h): digital poles exp(s T), so mode frequencies and decay times are exact;
//  * the bow point, the bridge and the body are coupled through one small linear solve per sample that
//    leaves v = v_h + y0 f, so any friction law sees the classic load line f = (v - v_h)/y0.
// Real-time contract: prepare() allocates; reset() and step() never allocate, lock or call the system.
#include <memory>
#include <vector>

#include "core/physics/bow/BowHair.h"
#include "core/physics/friction/FrictionLaw.h"
#include "core/physics/modal/ModalKernels.h"
#include "core/physics/voice/JunctionTerms.h"
#include "core/physics/voice/VoiceConfig.h"

namespace rosin::physics
{

class BridgeBody;

/// A voice's discrete system at its current bow position: what an engine that advances copies of the voice
/// needs (VoiceLanes). Pointers into the voice: valid until its next prepare(), bow-position or finger
/// change.
struct VoiceCoefficients
{
    const ModalBank* transverse = nullptr;
    const ModalBank* torsional = nullptr;
    const ModalReal* transverseForceGain = nullptr;  ///< a_n: bow force -> transverse mode n
    const ModalReal* transverseBridgeGain = nullptr; ///< b_n: -u'' -> transverse mode n
    const ModalReal* torsionalForceGain = nullptr;
    const OutputWeights* transverseVelocity = nullptr;     ///< bow-point velocity history Sv
    const OutputWeights* transverseAcceleration = nullptr; ///< bridge-force history Sa
    const OutputWeights* torsionalVelocity = nullptr;      ///< Tv
    const BridgeBody* body = nullptr;
    JunctionTerms junction; ///< the per-sample solve: v = v_h + y0 f, F = R - c G
    HairTerms hair;         ///< the bow hair in series with the contact (admittance 0: rigid hair)
};

/// Per-sample bow input, already smoothed (see BowGesture), SI units.
struct BowInput
{
    double bowForce = 0.0;    ///< F_b, N (>= 0)
    double bowVelocity = 0.0; ///< v_b, m/s
    double beta = 0.1;        ///< bow-bridge distance / vibrating length, 0.01..0.5
    double fingerRatio = 1.0; ///< vibrating length / open length (1 = open string), 0.1..1
};

/// What one sample produced. Forces in N, velocities in m/s.
struct VoiceSample
{
    double bridgeForce = 0.0;        ///< transverse force of the string on the bridge (the audio output)
    double bowPointVelocity = 0.0;   ///< string surface velocity at the bow (transverse + torsional)
    double frictionForce = 0.0;      ///< force of the bow on the string
    double bowVelocity = 0.0;        ///< v_b used this sample
    double contactTemperature = 0.0; ///< K above ambient (0 for non-thermal laws)
    bool sticking = true;
};

class BowedStringVoice
{
  public:
    BowedStringVoice();
    ~BowedStringVoice();
    BowedStringVoice(const BowedStringVoice&) = delete;
    BowedStringVoice& operator=(const BowedStringVoice&) = delete;

    /// Off the audio thread. Takes ownership of the friction law and prepares it.
    void prepare(const VoiceConfig& config, std::unique_ptr<FrictionLaw> friction, double sampleRate);
    /// String, body and friction state back to rest. Real-time safe.
    void reset() noexcept;
    /// Advance one sample. Real-time safe.
    VoiceSample step(const BowInput& in) noexcept;

    // --- Inspection (tests, analysis, UI) ---
    double sampleRate() const noexcept { return sampleRate_; }
    int transverseModeCount() const noexcept;
    int torsionalModeCount() const noexcept;
    int bodyModeCount() const noexcept;
    /// Transverse mode frequencies (Hz) of the current vibrating length.
    std::vector<double> transverseModeFrequencies() const;
    /// Instantaneous bow-point admittance y0 (s/kg) at the current bow position: v = v_h + y0 f (the
    /// string's, over the ribbon; the hair's y_h is in series with it).
    double instantaneousAdmittance() const noexcept;
    /// Stored mechanical energy of string (transverse + torsional) and body, J, at the last step.
    double storedEnergy() const noexcept;
    /// Transverse string displacement at the bow point at the last step, m (excludes torsion).
    double bowPointDisplacement() const noexcept;
    const FrictionLaw& friction() const noexcept { return *friction_; }
    const VoiceConfig& config() const noexcept { return config_; }

    /// Applies a bow position and finger ratio now (step() applies them at its next control tick). Off the
    /// audio thread.
    void setBowPosition(double beta, double fingerRatio);
    /// The discrete system at the current bow position (see VoiceCoefficients).
    VoiceCoefficients coefficients() const noexcept;

    /// Put this string on a body owned elsewhere (BowedInstrument), or back on its own with nullptr. The
    /// voice then reads that body's histories and no longer advances it: the owner advances it once per
    /// sample with the sum of all strings' bridge forces. Off the audio thread, after prepare().
    void useSharedBody(BridgeBody* body);
    /// Bridge force of the last step, N.
    double lastBridgeForce() const noexcept;

    // --- Two-phase step, for several strings on one shared body (BowedInstrument) ---
    // step() is solveJunction(in, 0) followed by finishStep(G) with G this string's own bridge force.
    /// Phase 1: apply the bow input and solve the friction junction, taking the other strings' bridge force
    /// this sample to be `otherStringsForce` (a prediction). Returns R: this string's bridge force is R - c G
    /// once the total bridge force G is known (c = bridgeCoupling()).
    double solveJunction(const BowInput& in, double otherStringsForce) noexcept;
    /// c in F = R - c G, dimensionless.
    double bridgeCoupling() const noexcept;
    /// Phase 2: with the total bridge force G of this sample, drive the string's modes and report the sample.
    VoiceSample finishStep(double totalBridgeForce) noexcept;

    /// True if the last step produced a non-finite or runaway state and the voice reset itself.
    bool recoveredFromRunaway() const noexcept { return recovered_; }

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    std::unique_ptr<FrictionLaw> friction_;
    VoiceConfig config_;
    double sampleRate_ = 48000.0;
    bool recovered_ = false;
};

} // namespace rosin::physics
