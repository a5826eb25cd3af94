#pragma once
// Several bowed strings on one instrument (a cello's C2 G2 D3 A3, a violin's G3 D4 A4 E5), each with its own
// bow input and friction law, all answering at the same bridge. This is what the plugin and the offline
// MIDI renderer drive: one object, one step per sample for all strings.
//
// All strings stand on one bridge: the body is driven by the sum of their bridge forces, and every string
// hears the body's motion, so a bowed string sets the others ringing (sympathetic resonance) and the body is
// computed once. Each string's junction predicts the other strings' bridge force from the previous sample;
// once all junctions are solved the total bridge force follows exactly, and every string and the body are
// driven with it, so the linear system stays the exact discretised one (and passive). Outputs: the total
// bridge force, and what a listener hears, the sound the body radiates (BodyRadiation.h), with the bridge
// velocity beside it.
// Real-time contract as for BowedStringVoice: prepare() allocates; reset() and step() never allocate, lock or
// call the system.
#include <memory>
#include <string>
#include <vector>

#include "core/physics/body/BridgeBody.h"
#include "core/physics/laws/FrictionLawFactory.h"
#include "core/physics/voice/BowedStringVoice.h"

namespace rosin::physics
{

struct InstrumentConfig
{
    std::string name = "cello";            ///< "cello", "violin", or a preset's name
    std::vector<StringParameters> strings; ///< lowest to highest
    BodyParameters body;                   ///< shared bridge admittance (rigid when empty)
    /// The body the listener hears the strings through when `body` is rigid: the strings then see a rigid
    /// bridge (the lab's condition) and this body is driven one way by their force. Unused otherwise.
    BodyParameters soundBody;
    bool torsion = true;
    bool bendingStiffness = true;
    BowParameters bow; ///< every string's bow: ribbon width and hair (default: a rigid point)
    FrictionModel friction = FrictionModel::Plastic;
    ContactParameters contact = galluzzoContact();
    /// Modes of the strings and the body above this frequency are left out, Hz; 0 (the default, the full
    /// model) keeps everything below VoiceConfig's 0.45 fs. A lower band costs less (the live quality).
    double modeBandwidthHz = 0.0;
};

/// A cello: C2 G2 D3 A3 (StringParameters catalogue) on celloBody().
InstrumentConfig celloInstrument();
/// A violin: G3 D4 A4 E5 (the instrument E5 tuned to 659.26 Hz) on violinBody().
InstrumentConfig violinInstrument();

class BowedInstrument
{
  public:
    /// Off the audio thread.
    void prepare(const InstrumentConfig& config, double sampleRate);
    void reset() noexcept;
    /// Advance all strings one sample. `inputs` and `outputs` hold stringCount() entries. Returns the total
    /// bridge force (N).
    double step(const BowInput* inputs, VoiceSample* outputs) noexcept;
    /// Sound pressure at the listener (Pa) and bridge velocity (m/s) of the last step, from the shared body
    /// or, on a rigid bridge, from soundBody driven one way.
    double radiatedPressure() const noexcept { return sounding().radiatedPressure(); }
    double bridgeVelocity() const noexcept { return sounding().bridgeVelocity(); }

    int stringCount() const noexcept { return static_cast<int>(voices_.size()); }
    const InstrumentConfig& config() const noexcept { return config_; }
    const BowedStringVoice& voice(int i) const noexcept { return *voices_[static_cast<std::size_t>(i)]; }
    /// Open-string fundamental (Hz) of string i.
    double openFrequency(int i) const noexcept;
    /// True if any string reset itself after a runaway during the last step.
    bool recoveredFromRunaway() const noexcept { return recovered_; }
    /// Stored energy of all strings and the shared body at the last step, J.
    double storedEnergy() const noexcept;
    const BridgeBody& body() const noexcept { return body_; }

  private:
    InstrumentConfig config_;
    std::vector<std::unique_ptr<BowedStringVoice>> voices_;
    BridgeBody body_;
    BridgeBody listeningBody_; ///< soundBody, when body_ is rigid
    const BridgeBody& sounding() const noexcept { return body_.rigid() ? listeningBody_ : body_; }
    double lastTotal_ = 0.0; ///< total bridge force of the last sample, N
    bool recovered_ = false;
};

} // namespace rosin::physics
