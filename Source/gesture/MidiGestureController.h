#pragma once
// MIDI and host parameters -> per-string physics::BowInput, one sample at a time (JUCE-free).
//
// MIDI map (README "Playing Rosin"):
//   note on      a stroke on the note's string (StringChoice.h; the "string" parameter overrides it); the
//                finger stops the string at f_open / f_note. From rest: constant acceleration (Guettler) at
//                attackAcceleration x accelerationScale(velocity), force x attackForceScale(velocity).
//                The same note again while bowing, or any note while the bow is lifting (note-off and
//                note-on at the same time): a bow change (direction reversal, same constant acceleration).
//                Another note on a string that is bowing: a finger change (legato). Strokes from rest
//                alternate down-bow / up-bow.
//                A chord: if the chosen string is held by a key pressed less than 30 ms earlier, the note
//                moves to the next lower free string (double stops); a later overlapping note is legato.
//   note off     the bow lifts (force and speed to 0 over 20 ms) and the string rings; with CC64 held the
//                stroke continues until the pedal is released.
//   CC1          force x controllerFactor(value);     channel / poly pressure: force x controllerFactor
//   CC11, CC2    speed x controllerFactor(value)      CC21: beta x betaControllerFactor(value)
//   pitch bend   finger glide, +-2 semitones          CC120/123: all strokes lifted; CC121: controllers reset
// Host parameters (GestureParameters) give the nominal values; controllers scale them; results are clamped
// to the parameter ranges.
//
// Threading: prepare() on any non-audio thread; everything else on the audio thread, allocation-free.
// Events apply at the sample they are handled: the caller handles an event whose sampleOffset is k just
// before calling next() for sample k, which makes the output independent of the block size.
#include <array>
#include <cstdint>

#include "BowStroke.h"
#include "GestureEvent.h"
#include "GestureParameters.h"

namespace rosin::gesture
{

class MidiGestureController
{
  public:
    static constexpr int kMaxStrings = 8;
    static constexpr double kChordWindowSeconds = 0.03;

    /// openFrequenciesHz: ascending open-string fundamentals (count 1..kMaxStrings).
    void prepare(const double* openFrequenciesHz, int count, double sampleRate,
                 const StrokeSettings& settings = {});
    /// Every string at rest, controllers at their reset values. Keeps the parameters.
    void reset() noexcept;

    /// The host parameters for the following samples (once per block).
    void setParameters(const GestureParameters& parameters) noexcept { parameters_ = parameters; }
    const GestureParameters& parameters() const noexcept { return parameters_; }

    /// Applies one event now (before the next call to next()).
    void handleEvent(const GestureEvent& event) noexcept;
    /// The next sample for every string: writes stringCount() inputs.
    void next(physics::BowInput* inputs) noexcept;

    /// Every string lifts (end of a render, all-notes-off).
    void liftAll() noexcept;

    // --- Inspection (tests, editor) ---
    int stringCount() const noexcept { return count_; }
    double openFrequency(int s) const noexcept { return openFrequencies_[static_cast<std::size_t>(s)]; }
    /// The string a note-on would use now (override, default choice, double-stop move).
    int stringForNote(int note) const noexcept;
    /// Finger ratio for `note` on string s, before pitch bend.
    double fingerRatioFor(int s, int note) const noexcept;
    const BowStroke& stroke(int s) const noexcept { return strings_[static_cast<std::size_t>(s)].stroke; }
    /// The note string s plays or last played (-1: none since reset).
    int note(int s) const noexcept { return strings_[static_cast<std::size_t>(s)].note; }
    bool sustainPedal() const noexcept { return sustainPedal_; }

  private:
    struct StringState
    {
        BowStroke stroke;
        int note = -1;
        bool keyDown = false;
        bool heldByPedal = false; // key released while the pedal was down
        double finger = 1.0;      // f_open / f_note
        int polyPressure = -1;    // -1: none received for this note
        std::int64_t noteOnSample = 0;
    };

    void noteOn(int note, int velocity) noexcept;
    void noteOff(int note) noexcept;
    void controller(int number, int value) noexcept;
    void resetControllers() noexcept;
    double forceFactor(const StringState& s) const noexcept;

    std::array<StringState, kMaxStrings> strings_{};
    std::array<double, kMaxStrings> openFrequencies_{};
    int count_ = 0;
    std::int64_t sampleCounter_ = 0; // samples since reset (chord window)
    std::int64_t chordWindowSamples_ = 1440;
    GestureParameters parameters_;
    int ccForce_ = 64, ccSpeed_ = 64, ccBeta_ = 64;
    int channelPressure_ = -1; // -1: none received
    double bendFactor_ = 1.0;  // finger multiplier from pitch bend
    bool sustainPedal_ = false;
};

} // namespace rosin::gesture
