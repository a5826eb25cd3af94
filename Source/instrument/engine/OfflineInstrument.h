#pragma once
// The instrument played without a host (`rosin render --midi`, tests): a program, its parameters and an
// optional measured body response; a MIDI sequence and automation lanes cut into blocks as a host would cut
// them, each block played by the same BlockPlayer as the plugin's processBlock. Every event lands at its own
// sample and automation moves on a fixed control grid, so a render does not depend on the block size, and it
// equals the plugin's output for the same program, parameters, events and blocks bit for bit
// (tests/instrument/plugin/OfflineRenderTest.cpp).
#include <optional>
#include <vector>

#include <juce_audio_basics/juce_audio_basics.h>

#include "instrument/engine/AutomationLanes.h"
#include "instrument/engine/BodyResponseFile.h"
#include "instrument/engine/FactoryPrograms.h"
#include "instrument/engine/InstrumentSetup.h"
#include "instrument/engine/ParameterSet.h"

namespace rosin::engine
{

struct MidiRenderSettings
{
    double sampleRate = 48000.0;
    int blockSize = 512;
    double tailSeconds = 2.0; ///< rendered after the last event, so the strings ring down
    int controlInterval = 64; ///< automation grid, samples
};

struct MidiRenderResult
{
    std::vector<float> audio; ///< the output (the plugin writes the same signal to every channel)
    float peak = 0.0f;
    int runawayResets = 0;
    int nonFiniteSamples = 0;
};

class OfflineInstrument
{
  public:
    /// A program's parameter values, extras and measured body response, as the plugin's program change sets
    /// them. A response the program names that cannot be read is reported on stderr; the one before stays.
    void setProgram(const FactoryProgram& program);
    /// The parameters (set plain values here before a render, as a user would).
    ParameterSet& parameters() noexcept { return parameters_; }
    /// Plays the sound through `response` instead of the modal body's radiation.
    void useBodyResponse(BodyResponseFile response);

    /// Renders `sequence` (timestamps in seconds) and `automation` from rest. The automation's values at 0 s
    /// are set before the instrument is built.
    MidiRenderResult render(const juce::MidiMessageSequence& sequence, const MidiRenderSettings& settings,
                            const AutomationLanes* automation = nullptr);

  private:
    ParameterSet parameters_;
    ProgramExtras extras_;
    std::optional<BodyResponseFile> response_;
};

/// Sets every automated parameter of `parameters` to its lane's value at `sample` where that changes its
/// normalised value; true if any changed. Lanes of unknown parameters are skipped.
bool applyAutomation(ParameterSet& parameters, const AutomationLanes& automation, std::int64_t sample,
                     double sampleRate);

/// The sample an event at `seconds` plays at: the one whose period [n, n + 1) / fs holds its time, as a host
/// that counts time in samples places it (Ardour does).
std::int64_t eventSample(double seconds, double sampleRate);

} // namespace rosin::engine
