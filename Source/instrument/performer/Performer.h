#pragma once
// The player at the instrument, sample by sample: gesture events in (MIDI-like, at their sample), the
// controller turns them and the block's settings into bow inputs for every string, the player's ear moves the
// fingers, the instrument steps, the regime meters listen. Every sample goes to a SampleSink (the plugin's
// output stage, a file, a test). JUCE-free: the plugin's processor is an adapter around it (host parameters
// -> BlockSettings, MidiBuffer -> EventSource, telemetry from the accessors below).
//
// Real-time contract: prepare() may allocate; follow(), reset(), beginBlock() and process() never allocate,
// lock or make a system call. Events are applied at their sample, so what is played does not depend on how
// the blocks are cut.
#include <array>

#include "core/analysis/LiveRegimeMeter.h"
#include "core/physics/instrument/BowedInstrument.h"
#include "instrument/player/GestureEvent.h"
#include "instrument/player/GestureParameters.h"
#include "instrument/player/IntonationEar.h"
#include "instrument/player/MidiGestureController.h"

namespace rosin::performer
{

/// Gesture events in sample order, pulled as the performer reaches their sample.
class EventSource
{
  public:
    virtual ~EventSource() = default;
    /// The next event stamped at or before `sample` (block-relative), applied at `sample`, if there is one.
    virtual bool next(int sample, player::GestureEvent& event) noexcept = 0;
    /// The next event left whatever its stamp (after the block's last sample), applied at `sample`.
    virtual bool remaining(int sample, player::GestureEvent& event) noexcept = 0;
};

/// Where each sample goes, as soon as the instrument has stepped.
class SampleSink
{
  public:
    virtual ~SampleSink() = default;
    /// Sample i of the block: `instrument` has just stepped and its step returned `bridgeForce` (N).
    virtual void take(int i, const physics::BowedInstrument& instrument, double bridgeForce) noexcept = 0;
};

/// What holds for a whole block.
struct BlockSettings
{
    player::GestureParameters gesture;
    bool intonationByEar = true;
};

class Performer
{
  public:
    static constexpr int kMaxStrings = player::MidiGestureController::kMaxStrings;

    /// For an instrument with these open strings (ascending, Hz; 1..kMaxStrings) and `serial`: controller,
    /// ears and regime meters prepared, the gesture at rest.
    void prepare(long serial, const double* openFrequencies, int strings, double sampleRate);
    /// The instrument the next block plays. A rebuilt one (another serial) with the same open strings keeps
    /// the gesture going; other strings (an instrument switch) re-prepare the controller and the ears.
    void follow(long serial, const double* openFrequencies, int strings, double sampleRate) noexcept;
    /// The factor each string's bow force is multiplied by (player::MidiGestureController::setForceShares);
    /// after prepare() or follow().
    void setForceShares(const double* shares, int strings) noexcept
    {
        controller_.setForceShares(shares, strings);
    }
    /// Each string's playable band (player::MidiGestureController::setBands); after prepare() or follow().
    void setBands(const player::PlayableBand* bands, int strings) noexcept
    {
        controller_.setBands(bands, strings);
    }
    const player::MidiGestureController& controller() const noexcept { return controller_; }
    /// Gesture, ears and meters back to rest (the instrument is the caller's).
    void reset() noexcept;
    /// No instrument any more: the next follow() prepares the gesture whatever the strings.
    void release() noexcept { serial_ = -1; }

    /// At a block's start: the block's settings, before any of its events.
    void beginBlock(const BlockSettings& settings) noexcept;
    /// An event outside the sample stream (an on-screen keyboard's note at the block's start).
    void handleEvent(const player::GestureEvent& event) noexcept { controller_.handleEvent(event); }
    /// n samples of `instrument`, each handed to `sink`; then the events stamped past the block's end
    /// (malformed host data) are applied. Returns the number of samples after which a string reset itself
    /// from a runaway.
    int process(physics::BowedInstrument& instrument, EventSource& events, SampleSink& sink, int n) noexcept;

    int stringCount() const noexcept { return strings_; }
    /// String s's last bow input, last output and regime meter (for telemetry, between blocks).
    const physics::BowInput& input(int s) const noexcept { return inputs_[static_cast<std::size_t>(s)]; }
    const physics::VoiceSample& output(int s) const noexcept { return outputs_[static_cast<std::size_t>(s)]; }
    const analysis::LiveRegimeMeter& meter(int s) const noexcept
    {
        return meters_[static_cast<std::size_t>(s)];
    }

  private:
    void prepareGesture(const double* openFrequencies, int strings, double sampleRate) noexcept;

    player::MidiGestureController controller_;
    long serial_ = -1;
    int strings_ = 0;
    std::array<double, kMaxStrings> openFrequencies_{};
    std::array<physics::BowInput, kMaxStrings> inputs_{};
    std::array<physics::VoiceSample, kMaxStrings> outputs_{};
    std::array<analysis::LiveRegimeMeter, kMaxStrings> meters_{};
    std::array<player::IntonationEar, kMaxStrings> ears_{};
};

} // namespace rosin::performer
