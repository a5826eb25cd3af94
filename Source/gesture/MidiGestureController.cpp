#include "MidiGestureController.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "StringChoice.h"

namespace rosin::gesture
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
    for (auto& s : strings_)
        s.stroke.prepare(sampleRate, settings);
    reset();
}

void MidiGestureController::reset() noexcept
{
    for (auto& s : strings_)
    {
        s.stroke.reset();
        s.note = -1;
        s.keyDown = s.heldByPedal = false;
        s.finger = 1.0;
        s.polyPressure = -1;
    }
    resetControllers();
    sustainPedal_ = false;
    sampleCounter_ = 0;
}

void MidiGestureController::resetControllers() noexcept
{
    ccForce_ = ccSpeed_ = ccBeta_ = 64;
    channelPressure_ = -1;
    bendFactor_ = 1.0;
}

int MidiGestureController::stringForNote(int note) const noexcept
{
    if (parameters_.stringOverride >= 0 && parameters_.stringOverride < count_)
        return parameters_.stringOverride;
    const int preferred = defaultString(openFrequencies_.data(), count_, note);
    const auto taken = [&](int i)
    {
        const auto& s = strings_[static_cast<std::size_t>(i)];
        return s.keyDown && s.note != note && sampleCounter_ - s.noteOnSample < chordWindowSamples_;
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
    switch (e.type)
    {
    case GestureEvent::Type::NoteOn:
        if (e.value > 0)
            noteOn(e.number, e.value);
        else
            noteOff(e.number);
        break;
    case GestureEvent::Type::NoteOff:
        noteOff(e.number);
        break;
    case GestureEvent::Type::Controller:
        controller(e.number, e.value);
        break;
    case GestureEvent::Type::ChannelPressure:
        channelPressure_ = std::clamp(e.value, 0, 127);
        break;
    case GestureEvent::Type::PolyPressure:
        for (int i = 0; i < count_; ++i)
        {
            auto& s = strings_[static_cast<std::size_t>(i)];
            if (s.note == e.number)
                s.polyPressure = std::clamp(e.value, 0, 127);
        }
        break;
    case GestureEvent::Type::PitchBend:
    {
        // Bending up shortens the string: the finger slides towards the bridge.
        const double semitones =
            (std::clamp(e.value, 0, 16383) - 8192) / 8192.0 * midimap::pitchBendSemitones;
        bendFactor_ = std::exp2(-semitones / 12.0);
        break;
    }
    }
}

void MidiGestureController::noteOn(int note, int velocity) noexcept
{
    if (note < 0 || note > 127)
        return;
    const int index = stringForNote(note);
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
                               forceScale, std::clamp(finger * bendFactor_, 0.1, 1.0));
    // else: another note on a bowing string is a finger change under the moving bow (legato).
    s.note = note;
    s.finger = finger;
    s.keyDown = true;
    s.heldByPedal = false;
    s.polyPressure = -1;
    s.noteOnSample = sampleCounter_;
}

void MidiGestureController::noteOff(int note) noexcept
{
    for (int i = 0; i < count_; ++i)
    {
        auto& s = strings_[static_cast<std::size_t>(i)];
        if (s.note != note || !s.keyDown)
            continue;
        s.keyDown = false;
        if (sustainPedal_)
            s.heldByPedal = true;
        else
            s.stroke.lift();
    }
}

void MidiGestureController::controller(int number, int value) noexcept
{
    value = std::clamp(value, 0, 127);
    switch (number)
    {
    case midimap::ccForce:
        ccForce_ = value;
        break;
    case midimap::ccSpeed:
    case midimap::ccSpeedAlt:
        ccSpeed_ = value;
        break;
    case midimap::ccBeta:
        ccBeta_ = value;
        break;
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
    case midimap::ccResetAll:
        resetControllers();
        break;
    case midimap::ccAllNotesOff:
    case midimap::ccAllSoundOff:
        liftAll();
        break;
    default:
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

double MidiGestureController::forceFactor(const StringState& s) const noexcept
{
    const int pressure = s.polyPressure >= 0 ? s.polyPressure : channelPressure_;
    return midimap::controllerFactor(ccForce_) * (pressure >= 0 ? midimap::controllerFactor(pressure) : 1.0);
}

void MidiGestureController::next(physics::BowInput* inputs) noexcept
{
    ++sampleCounter_;
    const auto& p = parameters_;
    const double speed = std::clamp(p.bowSpeed * midimap::controllerFactor(ccSpeed_), ranges::bowSpeed.min,
                                    ranges::bowSpeed.max);
    const double beta =
        std::clamp(p.beta * midimap::betaControllerFactor(ccBeta_), ranges::beta.min, ranges::beta.max);
    for (int i = 0; i < count_; ++i)
    {
        auto& s = strings_[static_cast<std::size_t>(i)];
        StrokeTargets t;
        t.force = std::clamp(p.bowForce * forceFactor(s), ranges::bowForce.min, ranges::bowForce.max);
        t.speed = speed;
        t.beta = beta;
        t.finger = std::clamp(s.finger * bendFactor_, 0.1, 1.0);
        inputs[i] = s.stroke.next(t);
    }
}

} // namespace rosin::gesture
