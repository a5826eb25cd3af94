#pragma once
// The body as a discrete modal system driven by the bridge force ([Notes] eq. 5.2 and §5.1): one or several
// strings push the bridge with force F; the body answers with a bridge displacement u, velocity u' and
// acceleration u''. Each output is "history + direct * F" for the current sample, which is what the strings'
// junction solves need. The same modes also give what a listener hears: the radiated sound pressure, a
// weighted sum of the modes' accelerations (BodyRadiation.h). Real-time contract: configure() allocates;
// reset() and advance() do not.
#include "core/physics/body/BodyParameters.h"
#include "core/physics/modal/ModalKernels.h"

namespace rosin::physics
{

class BridgeBody
{
  public:
    /// Off the audio thread. Modes at or above modeLimit (rad/s) are left out; the bank is padded with silent
    /// modes to whole vectors. `radiates` false skips the pressure sum (a string's own body in the lab, whose
    /// sound nobody hears: radiatedPressure() then stays 0).
    void configure(const BodyParameters& body, double sampleRate, double modeLimit, bool radiates = true);
    void reset() noexcept;
    /// Feed this sample's total bridge force (N) and advance: the histories become those of the next sample.
    void advance(double bridgeForce) noexcept;

    bool rigid() const noexcept { return bank_.size() == 0; }
    int modeCount() const noexcept; ///< modes that are driven (padding excluded)

    // Outputs known before the current force (m, m/s, m/s^2).
    double displacementHistory() const noexcept { return uh_; }
    double velocityHistory() const noexcept { return udh_; }
    double accelerationHistory() const noexcept { return uddh_; }
    // Response to the current force, per newton.
    double displacementDirect() const noexcept { return U0_; }
    double velocityDirect() const noexcept { return U1_; }
    double accelerationDirect() const noexcept { return U2_; }

    /// Sound pressure at the listener (Pa) and bridge velocity (m/s) of the sample last advanced: its history
    /// plus its direct response to that sample's force.
    double radiatedPressure() const noexcept { return pressureNow_; }
    double bridgeVelocity() const noexcept { return velocityNow_; }

    /// Bridge displacement (m) and stored energy (J) at the last advanced sample.
    double displacementAtLastStep() const noexcept;
    double velocityAtLastStep() const noexcept;
    double energyAtLastStep() const noexcept;

    // The discrete system, for engines that advance copies of this body (VoiceLanes).
    const ModalBank& bank() const noexcept { return bank_; }
    const ModalReal* inputGains() const noexcept { return gainIn_.data(); } ///< 1/m_k, 0 for padding
    const OutputWeights& displacementWeights() const noexcept { return u_; }
    const OutputWeights& velocityWeights() const noexcept { return ud_; }
    const OutputWeights& accelerationWeights() const noexcept { return udd_; }

  private:
    ModalBank bank_;
    std::vector<double> gain_;      ///< 1/m_k, 0 for padding
    std::vector<ModalReal> gainIn_; ///< gain_ in the modal kernels' number type
    OutputWeights u_, ud_, udd_, p_;
    double uh_ = 0, udh_ = 0, uddh_ = 0, ph_ = 0;
    double U0_ = 0, U1_ = 0, U2_ = 0, P0_ = 0;
    double pressureNow_ = 0, velocityNow_ = 0;
    double lowpassCoefficient_ = 1.0; ///< the one-pole H of BodyRadiation.h, impulse invariant
    bool radiates_ = true;
    double compactPressure_ = 0; ///< the modes' sum before H
    double lastForce_ = 0;
};

} // namespace rosin::physics
