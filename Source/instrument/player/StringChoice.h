#pragma once
// Where a note is played: which string, and how far the finger shortens it. Pure functions (JUCE-free).
//
// Default string: the highest string whose open pitch is at or below the note, as a player chooses in first
// position. Open pitches are compared in equal-tempered semitones with a half-semitone tolerance, so a
// string tuned a few cents sharp of its nominal note (the violin E5 at 659.26 Hz) still takes that note.
// A note below the lowest string goes to the lowest string, open (the finger cannot lengthen a string).

namespace rosin::player
{

/// Equal temperament, A4 = 440 Hz: 440 * 2^((note - 69) / 12).
double noteFrequency(double midiNote) noexcept;
/// Fractional MIDI pitch of a frequency (Hz).
double pitchOfFrequency(double frequencyHz) noexcept;
/// Index (0 = lowest) of the string that plays `note`; openFrequencies are ascending, count >= 1.
int defaultString(const double* openFrequenciesHz, int count, double note) noexcept;
/// Vibrating / open length for `note` on a string with open fundamental f_open: f_open / f_note, clamped to
/// 0.1..1 (the physics' finger range).
double fingerRatio(double openFrequencyHz, double note) noexcept;

} // namespace rosin::player
