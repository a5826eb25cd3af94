#pragma once
// The host-automatable gesture parameters in SI units, as one plain snapshot (read once per block by the
// plugin), their ranges, and the MIDI mapping constants. JUCE-free.
#include "core/gesture/GestureLimits.h"

namespace rosin::player
{

namespace ranges
{
inline constexpr physics::Range bowForce{0.05, 5.0, "N"};
inline constexpr physics::Range bowSpeed{0.01, 1.0, "m/s"};
inline constexpr physics::Range attackAcceleration{0.05, 10.0, "m/s^2"};
inline constexpr physics::Range beta{0.02, 0.3, ""};
using gesture::limits::bowPressure;
using gesture::limits::dynamics;
using gesture::limits::slideTime;
using gesture::limits::tremoloRate;
using gesture::limits::vibratoDelay;
using gesture::limits::vibratoDepth;
using gesture::limits::vibratoRate;
} // namespace ranges

/// How MIDI and the host parameters become a bow: the lab's direct physical control, or a cellist's arm.
enum class Mapping : int
{
    Lab,    ///< CC1 force, CC11 speed, the parameters as set (the mapping of the lab programs)
    Musical ///< one dynamics control moves speed, force and beta inside the band (DynamicsPath.h)
};

/// What the left hand and the bow do with a note.
enum class Articulation : int
{
    Arco,     ///< bowed
    Pizzicato ///< plucked by a finger (Pluck.h)
};

struct GestureParameters
{
    double bowForce = 1.0;           ///< F_b, N: nominal force (CC1 and pressure scale it)
    double bowSpeed = 0.1;           ///< |v_b|, m/s: sustained speed (CC11/CC2 scale it)
    double attackAcceleration = 2.0; ///< m/s^2 at velocity 127 (Guettler's constant-acceleration start)
    double beta = 0.0899;            ///< bow position (CC21 scales it); the Galluzzo rig's [GWM2017]
    int stringOverride = -1;         ///< -1: automatic choice; else string index, 0 = lowest string
    Mapping mapping = Mapping::Lab;  ///< the musical programs set Musical
    // The musical mapping's own (Resources/docs/playing.md, "The musical mapping", gives their sources):
    double dynamics = 0.6;      ///< pp 0 .. ff 1 until CC11 or CC2 arrives
    double bowPressure = 0.5;   ///< flautando 0, normal 0.5, scratch 1, until CC20 or pressure arrives
    double vibratoDepth = 15.0; ///< cents (half the peak-to-peak), until CC1 arrives
    double vibratoRate = 5.5;   ///< Hz
    double vibratoDelay = 0.25; ///< s from the note's start; the depth then grows over as long again
    double slideTime = 0.25;    ///< s, the slowest slide (a slur at the lowest velocity)
    double tremoloRate = 12.0;  ///< bow changes per second while tremolo is on
    Articulation articulation = Articulation::Arco;
};

/// MIDI-to-gesture constants. Controllers scale the host parameters multiplicatively, so "no controller
/// sent" (the reset value 64) leaves the parameter as set and a controller swell is relative to it.
namespace midimap
{
inline constexpr int ccForce = 1;    ///< mod wheel
inline constexpr int ccSpeed = 11;   ///< expression
inline constexpr int ccSpeedAlt = 2; ///< breath
inline constexpr int ccBeta = 21;    ///< bow position
inline constexpr int ccSlide = 74;   ///< MPE slide (per note on a member channel): bow position, like CC21
inline constexpr int ccSustain = 64; ///< >= 64: keep bowing after note-off
inline constexpr int ccBowPressure = 20;  ///< musical mapping: place in the band (flautando .. scratch)
inline constexpr int ccTremolo = 17;      ///< musical mapping: >= 64 tremolo
inline constexpr int ccVibratoRate = 76;  ///< musical mapping: GM2's vibrato rate, 64 = the parameter
inline constexpr int ccVibratoDelay = 78; ///< musical mapping: GM2's vibrato delay, 64 = the parameter
inline constexpr int ccResetAll = 121;    ///< controllers back to their reset values
inline constexpr int ccAllNotesOff = 123;
inline constexpr int ccAllSoundOff = 120;
/// Full bend = +-2 semitones of finger glide (default; RPN 0 sets it per channel).
inline constexpr double pitchBendSemitones = 2.0;
/// MPE member channels' default bend range (MPE spec: +-48 semitones, so a finger can slide across keys).
inline constexpr double mpeMemberPitchBendSemitones = 48.0;
/// Keyswitches: notes below every instrument's lowest string (cello C2 = 36, violin G3 = 55) choose the
/// string of the following notes. keyswitchFirst + i selects string i (0 = lowest); keyswitchAuto returns to
/// the automatic choice.
inline constexpr int keyswitchAuto = 23;  ///< B0
inline constexpr int keyswitchFirst = 24; ///< C1: the lowest string
/// Musical mapping: the next stroke from rest goes down-bow / up-bow; arco and pizzicato; tremolo on/off.
inline constexpr int keyswitchDownBow = 16;   ///< E0
inline constexpr int keyswitchUpBow = 17;     ///< F0
inline constexpr int keyswitchArco = 19;      ///< G0
inline constexpr int keyswitchPizzicato = 20; ///< G#0
inline constexpr int keyswitchTremolo = 21;   ///< A0: toggles

/// Factor 2^((value - 64) / 32): 0.25 at 0, 1 at 64, 3.9 at 127 (force and speed controllers, pressure).
double controllerFactor(int value) noexcept;
/// Factor 2^((value - 64) / 64): 0.5 at 0, 1 at 64, 2 at 127 (bow position).
double betaControllerFactor(int value) noexcept;
/// Attack acceleration scale 0.25 + 0.75 velocity / 127 (a soft note starts slower).
double accelerationScale(int velocity) noexcept;
/// Initial-force scale 0.5 + velocity / 127 (a loud note bites harder; Guettler: more acceleration needs
/// more force for a clean start).
double attackForceScale(int velocity) noexcept;
} // namespace midimap

} // namespace rosin::player
