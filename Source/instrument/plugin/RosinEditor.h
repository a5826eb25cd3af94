#pragma once
// Rosin's editor: the host parameters as controls (ParameterControls), one lane of live readouts per string
// (StringLane) and a Schelleng diagram of the sounding string (SchellengDiagram). Live values come from the
// processor's Telemetry, lock-free atomics the audio thread writes once per block; a ~30 Hz timer reads them.
// An on-screen keyboard (mouse, or the computer keyboard once it has focus) plays without a MIDI controller.
#include <array>
#include <memory>

#include <juce_audio_processors/juce_audio_processors.h>
#include <juce_audio_utils/juce_audio_utils.h>

#include "instrument/plugin/ParameterControls.h"
#include "instrument/plugin/SchellengDiagram.h"
#include "instrument/plugin/StringLane.h"

namespace rosin::plugin
{

class RosinProcessor;

class RosinEditor : public juce::AudioProcessorEditor, private juce::Timer
{
  public:
    static constexpr int kDefaultWidth = 900, kDefaultHeight = 804;
    static constexpr int kLanes = 4;

    explicit RosinEditor(RosinProcessor& processor);
    ~RosinEditor() override;

    void paint(juce::Graphics& g) override;
    void resized() override;

    /// Reads the telemetry and updates the readouts now (the timer does this ~30 times a second).
    void refreshReadouts();

  private:
    void timerCallback() override { refreshReadouts(); }
    /// The musical mapping's dynamics path for the sounding string (none with the lab mapping).
    void addDynamicsPath(SchellengDiagram::State& state, const StringReadout* readout) const;

    RosinProcessor& processor_;
    ParameterControls controls_;
    std::array<std::unique_ptr<StringLane>, kLanes> lanes_;
    SchellengDiagram schelleng_;
    juce::MidiKeyboardComponent keyboard_;
    // The measured body response: load (a file chooser), back to the modal body, and what is in use.
    juce::TextButton loadResponse_{"Body response..."}, clearResponse_{"Modal body"};
    juce::Label responseStatus_;
    // A program from a file (a preset, such as fit_body.py writes for a player's own instrument).
    juce::TextButton loadProgram_{"Program file..."};
    std::unique_ptr<juce::FileChooser> chooser_;
    void chooseBodyResponse();
    void chooseProgramFile();
    juce::String shownProgram_;
    int soundingString_ = -1; // index from the lowest; the diagram follows the last bowed string
};

} // namespace rosin::plugin
