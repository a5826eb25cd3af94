#pragma once
// Rosin's AudioProcessor: the host's side of performer::Performer (MIDI and host parameters -> gesture ->
// BowedInstrument, sample by sample), with programs, state, engine builds, the output stage and telemetry.
// Shared by the plugin formats and the tests (library rosin_plugin_core). Each block is played by
// engine::BlockPlayer, as the offline render (`rosin render --midi`) plays it.
//
// Audio thread (processBlock): no allocation, lock or system call. Parameters are read once per block into a
// plain snapshot (direct atomic pointers); MIDI is applied at its sample offset, so the output does not
// depend on the block size; denormals are flushed; the output is sanitised (non-finite -> 0, then a soft clip
// below +-1: SoftClip.h) and a voice that runs away resets itself and is counted. Builder side
// (message-thread timer, prepareToPlay): a change of instrument, friction law, body, ambient temperature or
// program rebuilds the instrument there and hands it over through EngineSlot (lock-free). It takes effect at
// the next block boundary. While the host renders offline (isNonRealtime(): a DAW's export, LV2 freewheeling,
// VST3 kOffline) the block itself does that work first, so an export never depends on when the timer fired.
#include <array>
#include <atomic>
#include <mutex>
#include <optional>
#include <vector>

#include <juce_audio_processors/juce_audio_processors.h>

#include "instrument/engine/BlockPlayer.h"
#include "instrument/engine/FactoryPrograms.h"
#include "instrument/engine/InstrumentSetup.h"
#include "instrument/plugin/BodyResponse.h"
#include "instrument/plugin/EngineSlot.h"
#include "instrument/plugin/HostParameters.h"
#include "instrument/plugin/KeyboardQueue.h"
#include "instrument/plugin/ProgramFile.h"
#include "instrument/plugin/StringTelemetry.h"

namespace rosin::plugin
{

class RosinProcessor : public juce::AudioProcessor, private juce::Timer
{
  public:
    /// 2: the musical mapping's parameters (a version 1 state gets the lab mapping, migrateState).
    static constexpr int kStateVersion = 2;

    RosinProcessor();
    ~RosinProcessor() override;

    void prepareToPlay(double sampleRate, int maximumExpectedSamplesPerBlock) override;
    void releaseResources() override;
    void reset() override;
    bool isBusesLayoutSupported(const BusesLayout& layouts) const override;
    void processBlock(juce::AudioBuffer<float>& buffer, juce::MidiBuffer& midi) override;
    using juce::AudioProcessor::processBlock;

    juce::AudioProcessorEditor* createEditor() override;
    bool hasEditor() const override { return true; }

    const juce::String getName() const override { return "Rosin"; }
    bool acceptsMidi() const override { return true; }
    bool producesMidi() const override { return false; }
    bool isMidiEffect() const override { return false; }
    /// MPE lower zone (gesture/MidiChannels.h): hosts may route per-note expression to us.
    bool supportsMPE() const override { return true; }
    double getTailLengthSeconds() const override { return 3.0; }

    int getNumPrograms() override { return static_cast<int>(programs_.size()); }
    int getCurrentProgram() override { return currentProgram_; }
    void setCurrentProgram(int index) override;
    const juce::String getProgramName(int index) override;
    void changeProgramName(int, const juce::String&) override {}

    /// The plugin's own "bypass" parameter: silence, faded over one block.
    juce::AudioProcessorParameter* getBypassParameter() const override;

    void getStateInformation(juce::MemoryBlock& destData) override;
    void setStateInformation(const void* data, int sizeInBytes) override;

    // --- Rosin ---
    juce::AudioProcessorValueTreeState& parameters() noexcept { return state_; }
    /// Builder-side work: frees retired engines and builds one if the instrument parameters changed. Called
    /// by the message-thread timer, and by processBlock while the host renders offline (isNonRealtime()), the
    /// only time it runs on the audio thread.
    void serviceEngineBuilds();
    /// Sets a parameter by its plain value (its own unit), notifying the host, as a user's move would.
    void setParameterValue(const char* id, float value);
    /// Selects a program by preset name; false if there is none of that name.
    bool setProgramByName(const std::string& name);
    /// Plays the program in `file` (a preset, such as fit_body.py writes) instead of a factory program, until
    /// a factory program is selected; it is saved with the state. False, with the reason in
    /// programFileStatus(), if the file cannot be used: the program playing stays.
    bool loadProgramFile(const juce::File& file);
    /// What the last program-file load did (for the editor); empty before any.
    juce::String programFileStatus() const;
    /// The program playing, as the editor shows it: a factory program's name, or a file's program and path.
    juce::String programTitle() const;
    /// Voice resets after a runaway, and non-finite output samples, since prepareToPlay.
    int runawayResets() const noexcept { return runawayResets_.load(); }
    int nonFiniteSamples() const noexcept { return nonFiniteSamples_.load(); }
    /// The engine the audio thread uses (tests, offline tools; not thread-safe against a swap).
    const engine::Engine* activeEngine() const noexcept { return slot_.active(); }
    /// Per-string readouts for the editor, published by processBlock once per block (lock-free); before audio
    /// runs, the instrument's strings at rest.
    const Telemetry& telemetry() const noexcept { return telemetry_; }
    /// The measured body response (message thread): load, clear, status; saved with the state.
    BodyResponseSetting& bodyResponse() noexcept { return bodyResponse_; }
    /// The on-screen keyboard's state (message thread); its notes reach processBlock lock-free.
    juce::MidiKeyboardState& keyboardState() noexcept { return keyboardState_; }

  private:
    /// Brings a saved state of an older version up to this one, before replaceState.
    static void migrateState(juce::ValueTree& tree);
    /// What every program change does: the preset becomes the builder's, its slow settings parameter values.
    void applyProgram(int index, const config::Preset& preset, std::optional<ProgramFile> file);
    void timerCallback() override;

    juce::AudioProcessorValueTreeState state_;
    ParameterReader reader_;
    std::vector<engine::FactoryProgram> programs_;
    int currentProgram_ = 0;

    // Builder side, guarded by builderMutex_ (the audio thread never takes it).
    mutable std::mutex builderMutex_;
    engine::ProgramExtras extras_;
    int programGeneration_ = 0;
    std::optional<ProgramFile> programFile_; ///< the program playing when it came from a file
    juce::String programFileStatus_;
    engine::InstrumentKey lastBuiltKey_;
    int lastBuiltGeneration_ = -1;
    long nextSerial_ = 1;
    double sampleRate_ = 48000.0;
    bool prepared_ = false;

    EngineSlot slot_;

    // Audio thread state.
    engine::BlockPlayer player_;
    std::atomic<float>* bypass_ = nullptr;
    float bypassGain_ = 1.0f; ///< the gain the last block ended at (0 bypassed, 1 playing)
    std::atomic<bool> resetRequested_{false};
    // The destructor waits for a timer callback in flight (hosts may destroy us off the message thread).
    std::atomic<bool> closing_{false};
    std::atomic<int> timerCallbacksRunning_{0};
    std::atomic<int> runawayResets_{0};
    std::atomic<int> nonFiniteSamples_{0};
    Telemetry telemetry_;
    void publishTelemetry(const engine::Engine& engine) noexcept;
    /// Before prepareToPlay: the lanes and diagram show the current instrument's strings at rest.
    void publishIdleTelemetry();
    juce::MidiKeyboardState keyboardState_;
    KeyboardQueue keyboardQueue_;
    BodyResponseHandoff responseHandoff_;
    BodyResponseSetting bodyResponse_{responseHandoff_};
    /// Audio thread (or prepareToPlay): a response loaded or cleared since goes to the output stage.
    void collectBodyResponse() noexcept;
};

} // namespace rosin::plugin
