// The musical mapping of MidiGestureController (MidiGestureController.h): what a cellist's arm and left hand
// do with a keyboard's notes and controllers. Figures and their sources: Resources/docs/playing.md, "The
// musical mapping".
#include <algorithm>
#include <cmath>

#include "instrument/player/MidiGestureController.h"

namespace rosin::player
{

namespace
{
/// Attack from rest: Guettler's constant acceleration inside his wedge for the attack's force
/// (PlayableBand::attackAccelerationPerNewton), the velocity choosing the place: a soft note starts at the
/// wedge's slow side, a hard one at its fast side, with up to kAccentForce more force; the bow reaches its
/// speed within these bounds whatever the wedge says. The bounds and the accent are calibrations, set on the
/// cello grid of tests/instrument/player/playing_test.py (the wedge's centre and the lab mapping's 0.5-1.5x
/// accent started low notes too slowly); the violin grid and the cello grid a semitone up, never looked at
/// while setting them, are their check (Resources/docs/playing.md, "How playable it is").
constexpr double kSlowestAttackSeconds = 0.1, kFastestAttackSeconds = 0.01;
constexpr double kAccentForce = 0.25;
/// Pizzicato: the finger takes the string at beta 0.25 (the end of the fingerboard, [playing.md]), pulls it
/// 1-4 mm sideways (by velocity) in 12 ms with a grip twice what that displacement needs, and lets go.
constexpr double kPluckBeta = 0.25, kPluckSeconds = 0.012;
/// The end of the fingerboard stays where it is as the finger shortens the string.
double pluckBeta(double finger) noexcept
{
    return std::min(0.45, kPluckBeta / finger);
}
constexpr double kPluckMinMetres = 0.001, kPluckMaxMetres = 0.004;
/// A stopped pizzicato note ends when the finger relaxes onto the string: a light touch at rest.
constexpr double kDampingForce = 0.1;
/// Tremolo bow changes: from +v_b to -v_b in a quarter of a stroke (2 v_b / a = 2 share / rate).
constexpr double kTremoloReversalShare = 0.125;
constexpr double kOpenString = 0.999;
/// Samples between recomputations of the musical bow (pow and log per string).
constexpr std::int64_t kControlInterval = 32; // finger ratio at or above: open, no vibrato
} // namespace

double MidiGestureController::musicalAcceleration(const PlayableBand& band, const MusicalBow& bow,
                                                  int velocity, double finger) const noexcept
{
    const double w = std::clamp(velocity, 1, 127) / 127.0;
    const double perNewton = band.attackAccelerationPerNewton(bow.beta, finger, w);
    const double force = bow.bowForce * accent(bow, velocity);
    const double wedge = perNewton > 0.0 ? perNewton * force : bow.bowSpeed / 0.05;
    return std::clamp(wedge, bow.bowSpeed / kSlowestAttackSeconds, bow.bowSpeed / kFastestAttackSeconds);
}

double MidiGestureController::accent(const MusicalBow& bow, int velocity) noexcept
{
    // The velocity's extra attack force, kept below the band's upper edge (a scratch is not an accent)
    // unless the bow already plays above it on purpose.
    const double scale = 1.0 + kAccentForce * std::clamp(velocity, 0, 127) / 127.0;
    if (bow.bowForce >= bow.upperForce || !(bow.bowForce > 0.0))
        return std::min(scale, 1.0);
    return std::min(scale, bow.upperForce / bow.bowForce);
}

MusicalBow MidiGestureController::musicalBowFor(int index, const ChannelControls& c) const noexcept
{
    const auto& s = strings_[static_cast<std::size_t>(index)];
    const double d = c.dynamics >= 0.0 ? c.dynamics : parameters_.dynamics;
    const double q = s.rawPolyPressure >= 0.0 ? s.rawPolyPressure
                     : c.bowPressure >= 0.0   ? c.bowPressure
                                              : parameters_.bowPressure;
    return musicalBow(path_, bands_[static_cast<std::size_t>(index)], d, q, c.beta);
}

void MidiGestureController::musicalNoteOn(int index, int channel, int note, int velocity) noexcept
{
    auto& s = strings_[static_cast<std::size_t>(index)];
    const double finger = fingerRatioFor(index, note);
    const auto phase = s.stroke.phase();
    if (articulation() == Articulation::Pizzicato)
        pluck(s, index, velocity, finger);
    else if ((s.stroke.bowing() && s.note == note) || phase == BowStroke::Phase::Release)
    {
        const MusicalBow bow = musicalBowFor(index, channels_.controls(channel));
        s.stroke.bowChange(
            musicalAcceleration(bands_[static_cast<std::size_t>(index)], bow, velocity, finger),
            accent(bow, velocity));
        s.lastBowChange = sampleCounter_;
    }
    else if (s.stroke.bowing())
    {
        // A slur on the same string: the finger falls or slides (FingerGlide.h); the vibrato goes on.
        s.glide.start(s.finger, finger, slurSeconds(velocity, parameters_.slideTime));
        s.gliding = true;
        if (finger >= kOpenString)
            s.vibrato.stop();
        else if (!s.vibrato.active())
            s.vibrato.startNote(++noteSerial_);
    }
    else if (!slurAcross(index, finger))
        musicalStart(s, index, channel, velocity, finger);
    s.note = note;
    s.channel = channel;
    s.finger = finger; // while gliding, the glide's target
    s.keyDown = true;
    s.heldByPedal = false;
    s.polyPressure = s.rawPolyPressure = -1.0;
    s.noteOnSample = sampleCounter_;
    s.bowValid = false;
}

void MidiGestureController::musicalStart(StringState& s, int index, int channel, int velocity,
                                         double finger) noexcept
{
    const ChannelControls c = channels_.controls(channel);
    s.rawPolyPressure = -1.0;
    const MusicalBow bow = musicalBowFor(index, c);
    const double direction = nextDirection_ != 0.0             ? nextDirection_
                             : s.stroke.strokesFromRest() == 0 ? 1.0
                                                               : -s.stroke.direction();
    nextDirection_ = 0.0;
    s.stroke.startFromRest(
        direction, musicalAcceleration(bands_[static_cast<std::size_t>(index)], bow, velocity, finger),
        accent(bow, velocity), std::clamp(finger * c.finger, 0.1, 1.0));
    s.glide.reset();
    s.gliding = false;
    s.lastBowChange = sampleCounter_;
    if (finger >= kOpenString)
        s.vibrato.stop();
    else
        s.vibrato.startNote(++noteSerial_);
}

bool MidiGestureController::slurAcross(int index, double finger) noexcept
{
    // The note overlaps one bowing on another string, and is no part of a chord: the bow crosses, still
    // moving, and the finger is already down on the new string; the hand's vibrato goes with it.
    for (int i = 0; i < count_; ++i)
    {
        auto& o = strings_[static_cast<std::size_t>(i)];
        if (i == index || !o.keyDown || !o.stroke.bowing() ||
            sampleCounter_ - o.noteOnSample < chordWindowSamples_)
            continue;
        auto& s = strings_[static_cast<std::size_t>(index)];
        s.stroke.crossOnto(o.stroke.velocity(), finger);
        s.vibrato = o.vibrato;
        if (finger >= kOpenString)
            s.vibrato.stop();
        s.glide.reset();
        s.gliding = false;
        s.lastBowChange = o.lastBowChange;
        o.keyDown = false;
        o.heldByPedal = false;
        o.stroke.lift(StrokeSettings{}.crossingSeconds);
        return true;
    }
    return false;
}

void MidiGestureController::pluck(StringState& s, int index, int velocity, double finger) noexcept
{
    const PlayableBand& band = bands_[static_cast<std::size_t>(index)];
    const double vibratingFrequency = openFrequencies_[static_cast<std::size_t>(index)] / finger;
    const double metres =
        kPluckMinMetres + (kPluckMaxMetres - kPluckMinMetres) * std::clamp(velocity, 1, 127) / 127.0;
    // The string's pull at that displacement: T/L (1/beta + 1/(1 - beta)) d, and T/L = 2 Z0 f of the
    // vibrating length (Z0 = T / c, c = 2 L f).
    const double z0 = band.valid() ? band.Z0 : 0.5;
    const double mu = band.valid() ? band.muStatic : 1.2;
    const double beta = pluckBeta(finger);
    const double pull = 2.0 * z0 * vibratingFrequency * (1.0 / beta + 1.0 / (1.0 - beta)) * metres;
    const double grip = std::clamp(2.0 * pull / mu, ranges::bowForce.min, kMusicalForceMax);
    s.stroke.pluck(metres / kPluckSeconds, grip, kPluckSeconds, finger);
    s.glide.reset();
    s.gliding = false;
    s.vibrato.stop(); // a plucked note rings with the finger still; vibrato after a pluck is rare
}

void MidiGestureController::musicalNoteOff(StringState& s) noexcept
{
    const auto phase = s.stroke.phase();
    const bool plucked = phase == BowStroke::Phase::Pluck || phase == BowStroke::Phase::Idle ||
                         (phase == BowStroke::Phase::Release && articulation() == Articulation::Pizzicato);
    if (plucked && s.finger < kOpenString)
        s.stroke.damp(kDampingForce); // the stopping finger relaxes: a stopped note dies, an open one rings
    else
        s.stroke.lift();
}

void MidiGestureController::musicalNext(physics::BowInput* inputs) noexcept
{
    const auto& p = parameters_;
    for (int i = 0; i < count_; ++i)
    {
        auto& s = strings_[static_cast<std::size_t>(i)];
        const ChannelControls c = channels_.controls(s.channel);
        // The bow follows its controls at a control rate (the stroke's 3 ms smoothers take the steps out);
        // the counter is the controller's own, so the result does not depend on the host's blocks.
        if (sampleCounter_ % kControlInterval == 1 || !s.bowValid)
        {
            s.bow = musicalBowFor(i, c);
            s.bowValid = true;
        }
        const MusicalBow& bow = s.bow;
        const double depth = c.vibrato >= 0.0 ? c.vibrato * ranges::vibratoDepth.max : p.vibratoDepth;
        const double nominal = s.gliding ? s.glide.next() : s.finger;
        s.gliding = s.gliding && s.glide.gliding();
        const double vibrato =
            s.vibrato.next(depth, p.vibratoRate * c.vibratoRate, p.vibratoDelay * c.vibratoDelay);
        if ((c.tremolo || tremoloKeyswitch_) && s.stroke.bowing() &&
            static_cast<double>(sampleCounter_ - s.lastBowChange) * p.tremoloRate >= sampleRate_)
        {
            s.stroke.bowChange(bow.bowSpeed * p.tremoloRate / kTremoloReversalShare, 1.0);
            s.lastBowChange = sampleCounter_;
        }
        StrokeTargets t;
        t.bowForce = bow.bowForce;
        t.bowSpeed = bow.bowSpeed;
        const bool plucking = s.stroke.phase() == BowStroke::Phase::Pluck;
        t.beta = plucking ? pluckBeta(s.finger) : bow.beta;
        t.finger = std::clamp(nominal * c.finger * vibrato, 0.1, 1.0);
        inputs[i] = s.stroke.next(t);
    }
}

} // namespace rosin::player
