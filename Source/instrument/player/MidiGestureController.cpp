#include "instrument/player/MidiGestureController.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "instrument/player/StringChoice.h"

namespace rosin::player
{

void MidiGestureController::prepare(const double* openFrequenciesHz, int count, double sampleRate,
                                    const StrokeSettings& settings)
{
    if (count < 1 || count > kMaxStrings)
        throw std::invalid_argument("MidiGestureController: 1..8 strings");
    if (!(sampleRate > 0.0))
        throw std::invalid_argument("MidiGestureController: sample rate must be positive");
    count_ = count;
    chordWindowSamples_ = static_cast<std::int64_t>(std::llround(kChordWindowSeconds * sampleRate));
    for (int i = 0; i < count; ++i)
        openFrequencies_[static_cast<std::size_t>(i)] = openFrequenciesHz[i];
    sampleRate_ = sampleRate;
    forceShares_ = unitShares();
    bands_ = {};
    for (std::size_t i = 0; i < strings_.size(); ++i)
    {
        auto& s = strings_[i];
        s.stroke.prepare(sampleRate, settings);
        s.vibrato.prepare(sampleRate, static_cast<std::uint32_t>(0x5eed + 7919 * i));
        s.glide.prepare(sampleRate);
    }
    reset();
}

void MidiGestureController::setBands(const PlayableBand* bands, int count) noexcept
{
    bands_ = {};
    std::copy(bands, bands + std::min(count, count_), bands_.begin());
}

Articulation MidiGestureController::articulation() const noexcept
{
    if (articulationKeyswitch_ >= 0)
        return static_cast<Articulation>(articulationKeyswitch_);
    return parameters_.articulation;
}

void MidiGestureController::setForceShares(const double* shares, int count) noexcept
{
    forceShares_ = unitShares();
    const int n = std::min(count, count_);
    if (n < 1 || !std::all_of(shares, shares + n, [](double x) { return x > 0.0 && std::isfinite(x); }))
        return;
    std::copy(shares, shares + n, forceShares_.begin());
}

void MidiGestureController::reset() noexcept
{
    for (auto& s : strings_)
    {
        s.stroke.reset();
        s.note = -1;
        s.channel = 1;
        s.keyDown = s.heldByPedal = false;
        s.finger = 1.0;
        s.polyPressure = s.rawPolyPressure = -1.0;
        s.vibrato.reset();
        s.glide.reset();
        s.gliding = false;
        s.bowValid = false;
    }
    channels_.resetControllers();
    keyswitchString_ = -1;
    noteSerial_ = 0;
    nextDirection_ = 0.0;
    articulationKeyswitch_ = -1;
    tremoloKeyswitch_ = false;
    sustainPedal_ = false;
    sampleCounter_ = 0;
}

bool MidiGestureController::isKeyswitch(int note) const noexcept
{
    // Only below the lowest string (the defaultString tolerance): a keyswitch never hides a playable note.
    const bool below = note + 0.5 < pitchOfFrequency(openFrequencies_[0]);
    const bool stroke = note >= midimap::keyswitchDownBow && note <= midimap::keyswitchTremolo &&
                        note != midimap::keyswitchUpBow + 1;
    return below && (stroke || (note >= midimap::keyswitchAuto && note < midimap::keyswitchFirst + count_));
}

int MidiGestureController::stringForNote(int note, int channel) const noexcept
{
    if (isKeyswitch(note))
        return -1;
    if (parameters_.stringOverride >= 0 && parameters_.stringOverride < count_)
        return parameters_.stringOverride;
    // MPE: one string per member channel; a new note on it while a key is down is a finger change there.
    if (channels_.isMemberChannel(channel))
        for (int i = 0; i < count_; ++i)
        {
            const auto& s = strings_[static_cast<std::size_t>(i)];
            if (s.keyDown && s.channel == channel)
                return i;
        }
    if (keyswitchString_ >= 0 && keyswitchString_ < count_)
        return keyswitchString_;
    const int preferred = defaultString(openFrequencies_.data(), count_, note);
    const auto taken = [&](int i)
    {
        const auto& s = strings_[static_cast<std::size_t>(i)];
        return s.keyDown && (s.note != note || s.channel != channel) &&
               sampleCounter_ - s.noteOnSample < chordWindowSamples_;
    };
    // Double stops: a string just taken by another key of the same chord passes the note to the next lower
    // free string, which can always reach it (a lower open pitch, a shorter finger stop).
    for (int i = preferred; i >= 0; --i)
        if (!taken(i))
            return i;
    return preferred;
}

double MidiGestureController::fingerRatioFor(int s, int note) const noexcept
{
    return fingerRatio(openFrequencies_[static_cast<std::size_t>(s)], note);
}

void MidiGestureController::handleEvent(const GestureEvent& e) noexcept
{
    if (e.channel < 1 || e.channel > MidiChannels::kChannels)
        return;
    switch (e.type)
    {
    case GestureEvent::Type::NoteOn:
        if (e.value > 0)
            noteOn(e.channel, e.number, e.value);
        else
            noteOff(e.channel, e.number);
        break;
    case GestureEvent::Type::NoteOff:
        noteOff(e.channel, e.number);
        break;
    case GestureEvent::Type::Controller:
        controller(e.channel, e.number, e.value);
        break;
    case GestureEvent::Type::ChannelPressure:
        channels_.pressure(e.channel, std::clamp(e.value, 0, 127));
        break;
    case GestureEvent::Type::PolyPressure:
        for (int i = 0; i < count_; ++i)
        {
            auto& s = strings_[static_cast<std::size_t>(i)];
            if (s.note == e.number && s.channel == e.channel)
            {
                s.polyPressure = midimap::controllerFactor(e.value);
                s.rawPolyPressure = std::clamp(e.value, 0, 127) / 127.0;
            }
        }
        break;
    case GestureEvent::Type::PitchBend:
        channels_.pitchBend(e.channel, e.value);
        break;
    }
}

void MidiGestureController::noteOn(int channel, int note, int velocity) noexcept
{
    if (note < 0 || note > 127)
        return;
    if (isKeyswitch(note))
    {
        if (!articulationKeyswitch(note))
            keyswitchString_ = note == midimap::keyswitchAuto ? -1 : note - midimap::keyswitchFirst;
        return;
    }
    const int index = stringForNote(note, channel);
    if (parameters_.mapping == Mapping::Musical)
    {
        musicalNoteOn(index, channel, note, velocity);
        return;
    }
    auto& s = strings_[static_cast<std::size_t>(index)];
    const double acceleration = parameters_.attackAcceleration * midimap::accelerationScale(velocity);
    const double forceScale = midimap::attackForceScale(velocity);
    const double finger = fingerRatioFor(index, note);
    const auto phase = s.stroke.phase();
    if ((s.stroke.bowing() && s.note == note) || phase == BowStroke::Phase::Release)
        // The same note again, or any note while the bow is still lifting (a note-off and note-on at the same
        // time, as a sequencer writes repeated or detache notes): reverse the bow.
        s.stroke.bowChange(acceleration, forceScale);
    else if (phase == BowStroke::Phase::Idle)
        // From rest; strokes alternate down-bow / up-bow, the first one after reset is a down-bow.
        s.stroke.startFromRest(s.stroke.strokesFromRest() == 0 ? 1.0 : -s.stroke.direction(), acceleration,
                               forceScale, std::clamp(finger * channels_.controls(channel).finger, 0.1, 1.0));
    // else: another note on a bowing string is a finger change under the moving bow (legato).
    s.note = note;
    s.channel = channel;
    s.finger = finger;
    s.keyDown = true;
    s.heldByPedal = false;
    s.polyPressure = -1.0;
    s.noteOnSample = sampleCounter_;
}

void MidiGestureController::noteOff(int channel, int note) noexcept
{
    if (isKeyswitch(note))
        return;
    for (int i = 0; i < count_; ++i)
    {
        auto& s = strings_[static_cast<std::size_t>(i)];
        if (s.note != note || s.channel != channel || !s.keyDown)
            continue;
        s.keyDown = false;
        if (sustainPedal_ && s.stroke.phase() != BowStroke::Phase::Pluck)
            s.heldByPedal = true;
        else if (parameters_.mapping == Mapping::Musical)
            musicalNoteOff(s);
        else
            s.stroke.lift();
    }
}

bool MidiGestureController::articulationKeyswitch(int note) noexcept
{
    switch (note)
    {
    case midimap::keyswitchDownBow:
        nextDirection_ = 1.0;
        return true;
    case midimap::keyswitchUpBow:
        nextDirection_ = -1.0;
        return true;
    case midimap::keyswitchArco:
        articulationKeyswitch_ = static_cast<int>(Articulation::Arco);
        return true;
    case midimap::keyswitchPizzicato:
        articulationKeyswitch_ = static_cast<int>(Articulation::Pizzicato);
        return true;
    case midimap::keyswitchTremolo:
        tremoloKeyswitch_ = !tremoloKeyswitch_;
        return true;
    default:
        return false;
    }
}

void MidiGestureController::controller(int channel, int number, int value) noexcept
{
    value = std::clamp(value, 0, 127);
    switch (number)
    {
    case midimap::ccSustain:
        sustainPedal_ = value >= 64;
        if (!sustainPedal_)
            for (int i = 0; i < count_; ++i)
            {
                auto& s = strings_[static_cast<std::size_t>(i)];
                if (s.heldByPedal)
                {
                    s.heldByPedal = false;
                    s.stroke.lift();
                }
            }
        break;
    case midimap::ccAllNotesOff:
    case midimap::ccAllSoundOff:
        liftAll();
        break;
    default:
        channels_.controller(channel, number, value);
        break;
    }
}

void MidiGestureController::liftAll() noexcept
{
    for (int i = 0; i < count_; ++i)
    {
        auto& s = strings_[static_cast<std::size_t>(i)];
        s.keyDown = s.heldByPedal = false;
        s.stroke.lift();
    }
}

void MidiGestureController::next(physics::BowInput* inputs) noexcept
{
    ++sampleCounter_;
    if (parameters_.mapping == Mapping::Musical)
    {
        musicalNext(inputs);
        return;
    }
    const auto& p = parameters_;
    for (int i = 0; i < count_; ++i)
    {
        auto& s = strings_[static_cast<std::size_t>(i)];
        const ChannelControls c = channels_.controls(s.channel);
        const double pressure = s.polyPressure >= 0.0 ? s.polyPressure : c.pressure;
        StrokeTargets t;
        t.bowForce = std::clamp(p.bowForce * forceShares_[static_cast<std::size_t>(i)] * (c.force * pressure),
                                ranges::bowForce.min, ranges::bowForce.max);
        t.bowSpeed = std::clamp(p.bowSpeed * c.speed, ranges::bowSpeed.min, ranges::bowSpeed.max);
        t.beta = std::clamp(p.beta * c.beta, ranges::beta.min, ranges::beta.max);
        t.finger = std::clamp(s.finger * c.finger, 0.1, 1.0);
        inputs[i] = s.stroke.next(t);
    }
}

} // namespace rosin::player
