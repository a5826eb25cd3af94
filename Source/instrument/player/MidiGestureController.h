#pragma once
// MIDI and host parameters -> per-string physics::BowInput, one sample at a time (JUCE-free).
//
// MIDI map (Resources/docs/playing.md, "MIDI map"):
//   note on      a stroke on the note's string: the "string" parameter if set, else the keyswitch choice,
//                else the default choice (StringChoice.h); the finger stops the string at f_open / f_note.
//                From rest: constant acceleration (Guettler) at attackAcceleration x
//                accelerationScale(velocity), force x attackForceScale(velocity). The same note again while
//                bowing, or any note while the bow is lifting (note-off and note-on at the same time): a bow
//                change (direction reversal, same constant acceleration). Another note on a string that is
//                bowing: a finger change (legato). Strokes from rest alternate down-bow / up-bow. A chord: if
//                the chosen string is held by a key pressed less than 30 ms earlier, the note moves to the
//                next lower free string (double stops); a later overlapping note is legato.
//   keyswitch    notes midimap::keyswitchFirst + i (below the lowest string) choose string i for the
//                following notes, midimap::keyswitchAuto the default choice again; they never bow.
//   note off     the bow lifts (force and speed to 0 over 20 ms) and the string rings; with CC64 held the
//                stroke continues until the pedal is released.
//   CC1          force x controllerFactor(value);     channel / poly pressure: force x controllerFactor
//   CC11, CC2    speed x controllerFactor(value)      CC21, CC74: beta x betaControllerFactor(value)
//   pitch bend   finger glide, +-2 semitones (RPN 0)  CC120/123: all strokes lifted; CC121: controllers reset
// Controllers, pressure and bend are per channel: a string follows the channel of the note it plays
// (MidiChannels.h). MPE lower zone (RPN 6 on channel 1): the master channel applies to every string, a
// member channel's pressure, CC74 and bend (+-48) to its note only, and a member channel keeps its string
// while it holds a note (a new note on it is a legato finger change). CC64 and CC120/123 act on all strings.
// Host parameters (GestureParameters) give the nominal values; controllers scale them; results are clamped
// to the parameter ranges. Each string gets its own share of the bow force (setForceShares; the engine gives
// shares in proportion to the strings' impedances, engine::bowForceShare).
//
// The musical mapping (GestureParameters::mapping; MusicalMapping.cpp, Resources/docs/playing.md): CC11/CC2
// are dynamics along a DynamicsPath, CC20 and pressure the bow pressure inside each string's PlayableBand,
// CC1 the vibrato depth (Vibrato.h; CC76 rate, CC78 delay), overlapping notes slur with a finger placed or
// slid by the landing velocity (FingerGlide.h) or cross strings under a moving bow, CC17 or keyswitch A0
// tremolo, keyswitches E0/F0 the next stroke's direction, G0/G#0 arco/pizzicato.
//
// Threading: prepare() on any non-audio thread; everything else on the audio thread, allocation-free.
// Events apply at the sample they are handled: the caller handles an event whose sampleOffset is k just
// before calling next() for sample k, which makes the output independent of the block size.
#include <array>
#include <cstdint>

#include "instrument/player/BowStroke.h"
#include "instrument/player/DynamicsPath.h"
#include "instrument/player/FingerGlide.h"
#include "instrument/player/GestureEvent.h"
#include "instrument/player/GestureParameters.h"
#include "instrument/player/MidiChannels.h"
#include "instrument/player/PlayableBand.h"
#include "instrument/player/Vibrato.h"

namespace rosin::player
{

class MidiGestureController
{
  public:
    static constexpr int kMaxStrings = 8;
    static constexpr double kChordWindowSeconds = 0.03;

    /// openFrequenciesHz: ascending open-string fundamentals (count 1..kMaxStrings).
    void prepare(const double* openFrequenciesHz, int count, double sampleRate,
                 const StrokeSettings& settings = {});
    /// The factor each prepared string's bow force is multiplied by; until set (and after prepare()), or if
    /// any is not positive and finite, 1 for every string.
    void setForceShares(const double* shares, int count) noexcept;
    /// The factor string s's bow force is multiplied by.
    double forceShare(int s) const noexcept { return forceShares_[static_cast<std::size_t>(s)]; }
    /// Each prepared string's playable band, for the musical mapping; until set, invalid bands (the
    /// classical curve's band of a generic string stands in).
    void setBands(const PlayableBand* bands, int count) noexcept;
    const PlayableBand& band(int s) const noexcept { return bands_[static_cast<std::size_t>(s)]; }
    const DynamicsPath& dynamicsPath() const noexcept { return path_; }
    /// Every string at rest, controllers at their reset values, automatic string choice. Keeps the
    /// parameters, the MPE zone and the pitch-bend ranges (configuration a controller sends once).
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
    /// The string a note-on on `channel` would use now (override, the member channel's string, keyswitch,
    /// default choice, double-stop move); -1 for a keyswitch note.
    int stringForNote(int note, int channel = 1) const noexcept;
    /// Whether `note` is a keyswitch (midimap::keyswitchAuto..keyswitchFirst + count - 1, below the lowest
    /// string).
    bool isKeyswitch(int note) const noexcept;
    /// The string chosen by keyswitch (-1: automatic choice).
    int keyswitchString() const noexcept { return keyswitchString_; }
    bool mpeEnabled() const noexcept { return channels_.mpeEnabled(); }
    int memberChannelCount() const noexcept { return channels_.memberChannelCount(); }
    const MidiChannels& channels() const noexcept { return channels_; }
    /// Finger ratio for `note` on string s, before pitch bend.
    double fingerRatioFor(int s, int note) const noexcept;
    const BowStroke& stroke(int s) const noexcept { return strings_[static_cast<std::size_t>(s)].stroke; }
    /// The note string s plays or last played (-1: none since reset).
    int note(int s) const noexcept { return strings_[static_cast<std::size_t>(s)].note; }
    /// The MIDI channel of that note (its controllers drive the string).
    int channel(int s) const noexcept { return strings_[static_cast<std::size_t>(s)].channel; }
    bool sustainPedal() const noexcept { return sustainPedal_; }
    /// String s's vibrato now, cents.
    double vibratoCents(int s) const noexcept
    {
        return strings_[static_cast<std::size_t>(s)].vibrato.cents();
    }
    /// The articulation a note-on gets now (a keyswitch overrides the parameter).
    Articulation articulation() const noexcept;
    /// Tremolo switched on by keyswitch.
    bool tremoloKeyswitch() const noexcept { return tremoloKeyswitch_; }

  private:
    struct StringState
    {
        BowStroke stroke;
        int note = -1;
        int channel = 1;
        bool keyDown = false;
        bool heldByPedal = false; // key released while the pedal was down
        double finger = 1.0;      // f_open / f_note
        double polyPressure = -1; // force factor; -1: none received for this note
        std::int64_t noteOnSample = 0;
        // musical mapping
        Vibrato vibrato;
        FingerGlide glide;
        bool gliding = false;
        double rawPolyPressure = -1.0; // 0..1; -1: none received for this note
        std::int64_t lastBowChange = 0;
        MusicalBow bow;        // the musical bow, recomputed at a control rate
        bool bowValid = false; // false: recompute at the next sample
    };

    static constexpr std::array<double, kMaxStrings> unitShares()
    {
        std::array<double, kMaxStrings> a{};
        a.fill(1.0);
        return a;
    }
    void noteOn(int channel, int note, int velocity) noexcept;
    void noteOff(int channel, int note) noexcept;
    void controller(int channel, int number, int value) noexcept;
    bool articulationKeyswitch(int note) noexcept;
    // MusicalMapping.cpp
    void musicalNoteOn(int index, int channel, int note, int velocity) noexcept;
    void musicalStart(StringState& s, int index, int channel, int velocity, double finger) noexcept;
    bool slurAcross(int index, double finger) noexcept;
    void musicalNoteOff(StringState& s) noexcept;
    void musicalNext(physics::BowInput* inputs) noexcept;
    void pluck(StringState& s, int index, int velocity, double finger) noexcept;
    double musicalAcceleration(const PlayableBand& band, const MusicalBow& bow, int velocity,
                               double finger) const noexcept;
    MusicalBow musicalBowFor(int index, const ChannelControls& c) const noexcept;
    static double accent(const MusicalBow& bow, int velocity) noexcept;

    std::array<StringState, kMaxStrings> strings_{};
    std::array<double, kMaxStrings> openFrequencies_{};
    std::array<double, kMaxStrings> forceShares_ = unitShares();
    std::array<PlayableBand, kMaxStrings> bands_{};
    DynamicsPath path_;
    double sampleRate_ = 48000.0;
    std::uint32_t noteSerial_ = 0;
    double nextDirection_ = 0.0; // keyswitch: +1 down-bow, -1 up-bow next, 0 alternate
    int articulationKeyswitch_ = -1;
    bool tremoloKeyswitch_ = false;
    int count_ = 0;
    std::int64_t sampleCounter_ = 0; // samples since reset (chord window)
    std::int64_t chordWindowSamples_ = 1440;
    GestureParameters parameters_;
    MidiChannels channels_;
    int keyswitchString_ = -1;
    bool sustainPedal_ = false;
};

} // namespace rosin::player
