#include "instrument/plugin/RosinEditor.h"

#include <cmath>

#include "instrument/player/DynamicsPath.h"
#include "instrument/plugin/RosinProcessor.h"

namespace rosin::plugin
{

namespace
{
constexpr int kHeaderHeight = 40;
constexpr int kControlsHeight = 346; // three selector rows and two rows of knobs
constexpr int kKeyboardHeight = 60;
constexpr int kProgramButtonWidth = 110;
constexpr int kLowestKey = 36, kHighestKey = 100; // cello C2 to the violin's E7
const char* const kRoman[] = {"I", "II", "III", "IV", "V", "VI", "VII", "VIII"};
} // namespace

RosinEditor::RosinEditor(RosinProcessor& processor)
    : juce::AudioProcessorEditor(processor), processor_(processor), controls_(processor.parameters()),
      keyboard_(processor.keyboardState(), juce::MidiKeyboardComponent::horizontalKeyboard)
{
    addAndMakeVisible(controls_);
    // Lanes top to bottom: string I (highest) first, as a player reads them.
    for (int i = 0; i < kLanes; ++i)
    {
        lanes_[static_cast<std::size_t>(i)] = std::make_unique<StringLane>(i + 1);
        addAndMakeVisible(*lanes_[static_cast<std::size_t>(i)]);
    }
    addAndMakeVisible(schelleng_);
    keyboard_.setAvailableRange(kLowestKey, kHighestKey);
    keyboard_.setLowestVisibleKey(kLowestKey);
    keyboard_.setOctaveForMiddleC(4);   // MIDI 60 = C4, as the manual names notes (C2 = 36)
    keyboard_.setKeyPressBaseOctave(4); // the computer keyboard's row starts at C4
    keyboard_.setWantsKeyboardFocus(true);
    addAndMakeVisible(keyboard_);
    addAndMakeVisible(loadResponse_);
    addAndMakeVisible(clearResponse_);
    addAndMakeVisible(responseStatus_);
    loadResponse_.setTooltip(
        "Load a measured body response: a WAV impulse response from bridge force (N) to sound "
        "pressure (Pa), used for the radiated sound");
    loadResponse_.onClick = [this] { chooseBodyResponse(); };
    clearResponse_.onClick = [this] { processor_.bodyResponse().clear(); };
    addAndMakeVisible(loadProgram_);
    loadProgram_.setTooltip("Play a program file (a preset in JSON, such as fit_body.py writes for your own "
                            "instrument) until a factory program is chosen; it is saved with the project");
    loadProgram_.onClick = [this] { chooseProgramFile(); };
    responseStatus_.setFont(juce::Font(12.0f));
    setResizable(true, true);
    setResizeLimits(780, 718, 1600, 1250);
    setSize(kDefaultWidth, kDefaultHeight);
    refreshReadouts();
    startTimerHz(30);
}

RosinEditor::~RosinEditor()
{
    stopTimer();
}

void RosinEditor::paint(juce::Graphics& g)
{
    g.fillAll(getLookAndFeel().findColour(juce::ResizableWindow::backgroundColourId));
    auto header = getLocalBounds().removeFromTop(kHeaderHeight).reduced(14, 0);
    g.setColour(getLookAndFeel().findColour(juce::Label::textColourId));
    g.setFont(juce::Font(24.0f, juce::Font::bold));
    g.drawText("Rosin", header, juce::Justification::centredLeft);
    g.setFont(juce::Font(13.0f));
    g.setColour(getLookAndFeel().findColour(juce::Label::textColourId).withAlpha(0.6f));
    g.drawText("physically modelled bowed string", header.withTrimmedLeft(86),
               juce::Justification::centredLeft);
    g.drawText("program: " + processor_.programTitle(), header.withTrimmedRight(kProgramButtonWidth + 8),
               juce::Justification::centredRight);
}

void RosinEditor::resized()
{
    auto area = getLocalBounds().reduced(10, 0);
    loadProgram_.setBounds(getLocalBounds()
                               .removeFromTop(kHeaderHeight)
                               .reduced(14, 0)
                               .removeFromRight(kProgramButtonWidth)
                               .reduced(0, 8));
    area.removeFromTop(kHeaderHeight);
    controls_.setBounds(area.removeFromTop(kControlsHeight));
    // Beside the output choice and the quality (the controls' second row): the body response's buttons and
    // status.
    auto responseRow = controls_.getBounds()
                           .withTrimmedTop(ParameterControls::kSelectorRowHeight)
                           .withHeight(ParameterControls::kSelectorRowHeight)
                           .withTrimmedLeft(ParameterControls::kSecondRowWidth + 10);
    loadResponse_.setBounds(responseRow.removeFromLeft(120).reduced(0, 3));
    clearResponse_.setBounds(responseRow.removeFromLeft(90).reduced(4, 3));
    responseStatus_.setBounds(responseRow);
    area.removeFromTop(8);
    area.removeFromBottom(10);
    keyboard_.setBounds(area.removeFromBottom(kKeyboardHeight));
    keyboard_.setKeyWidth(static_cast<float>(area.getWidth()) / 38.5f); // 38 white keys from C2 to E7
    area.removeFromBottom(8);
    auto lanes = area.removeFromLeft(area.getWidth() * 57 / 100);
    area.removeFromLeft(8);
    schelleng_.setBounds(area);
    const int laneHeight = lanes.getHeight() / kLanes;
    for (auto& lane : lanes_)
        lane->setBounds(lanes.removeFromTop(laneHeight));
}

void RosinEditor::chooseBodyResponse()
{
    chooser_ = std::make_unique<juce::FileChooser>("Body response (bridge force to sound pressure)",
                                                   juce::File(), "*.wav;*.aif;*.aiff;*.flac");
    chooser_->launchAsync(juce::FileBrowserComponent::openMode | juce::FileBrowserComponent::canSelectFiles,
                          [this](const juce::FileChooser& chooser)
                          {
                              if (chooser.getResult() != juce::File())
                                  processor_.bodyResponse().load(chooser.getResult());
                          });
}

void RosinEditor::chooseProgramFile()
{
    chooser_ = std::make_unique<juce::FileChooser>("Program file (a Rosin preset)", juce::File(), "*.json");
    chooser_->launchAsync(juce::FileBrowserComponent::openMode | juce::FileBrowserComponent::canSelectFiles,
                          [this](const juce::FileChooser& chooser)
                          {
                              if (chooser.getResult() == juce::File())
                                  return;
                              if (!processor_.loadProgramFile(chooser.getResult()))
                                  juce::AlertWindow::showMessageBoxAsync(
                                      juce::MessageBoxIconType::WarningIcon, "Program file not loaded",
                                      processor_.programFileStatus());
                              repaint();
                          });
}

void RosinEditor::refreshReadouts()
{
    if (const juce::String title = processor_.programTitle(); title != shownProgram_)
    {
        shownProgram_ = title; // a host's or a file's program change: the header names it
        repaint(getLocalBounds().removeFromTop(kHeaderHeight));
    }
    if (responseStatus_.getText() != processor_.bodyResponse().status())
    {
        responseStatus_.setText(processor_.bodyResponse().status(), juce::dontSendNotification);
        responseStatus_.setTooltip(processor_.bodyResponse().status());
    }
    const Telemetry& telemetry = processor_.telemetry();
    const int count =
        juce::jlimit(0, Telemetry::kMaxStrings, telemetry.stringCount.load(std::memory_order_relaxed));
    std::array<StringReadout, Telemetry::kMaxStrings> readouts{};
    float strongest = 0.0f;
    int bowed = -1;
    for (int s = 0; s < count; ++s)
    {
        readouts[static_cast<std::size_t>(s)] = telemetry.strings[static_cast<std::size_t>(s)].read();
        const auto& r = readouts[static_cast<std::size_t>(s)];
        if (r.bowing && r.bowForce > strongest)
            strongest = r.bowForce, bowed = s;
    }
    if (bowed >= 0)
        soundingString_ = bowed;
    if (soundingString_ >= count)
        soundingString_ = -1;

    // Lane i shows string I..IV: the telemetry counts from the lowest string.
    for (int i = 0; i < kLanes; ++i)
    {
        const int s = count - 1 - i;
        lanes_[static_cast<std::size_t>(i)]->setReadout(
            s >= 0 ? readouts[static_cast<std::size_t>(s)] : StringReadout{}, s >= 0);
    }

    SchellengDiagram::State state;
    const int s = soundingString_ >= 0 ? soundingString_ : count - 1;
    auto* speed = processor_.parameters().getRawParameterValue(ids::bowSpeed);
    auto* beta = processor_.parameters().getRawParameterValue(ids::beta);
    auto* force = processor_.parameters().getRawParameterValue(ids::bowForce);
    if (s >= 0)
    {
        const auto& r = readouts[static_cast<std::size_t>(s)];
        state.title =
            "string " + juce::String(kRoman[count - 1 - s]) + " (" +
            juce::MidiMessage::getMidiNoteName(
                static_cast<int>(std::lround(69.0 + 12.0 * std::log2(juce::jmax(1.0f, r.frequency) / 440.0))),
                true, true, 4) +
            ")";
        state.impedance = r.impedance;
        state.conductance = r.bridgeConductance;
        state.deltaMu = SchellengDiagram::effectiveDeltaMu(r.muStatic, r.muSlip);
        state.bowing = r.bowing;
        state.regime = r.regime;
        // Live bow values while bowing; the parameters' nominal ones otherwise.
        state.bowSpeed = r.bowing ? std::abs(r.bowVelocity) : speed->load();
        state.beta = r.bowing ? r.beta : beta->load();
        state.force = r.bowing ? r.bowForce : force->load();
    }
    else
    {
        state.title = "(not playing)";
        state.bowSpeed = speed->load();
        state.beta = beta->load();
        state.force = force->load();
    }
    addDynamicsPath(state, s >= 0 ? &readouts[static_cast<std::size_t>(s)] : nullptr);
    schelleng_.setState(state);
}

void RosinEditor::addDynamicsPath(SchellengDiagram::State& state, const StringReadout* readout) const
{
    const auto value = [this](const char* id)
    { return processor_.parameters().getRawParameterValue(id)->load(); };
    if (readout == nullptr || value(ids::mapping) < 0.5f)
        return;
    // The string's band as the engine built it (engine::playableBand), from what its telemetry reports.
    player::PlayableBand band;
    band.Z0 = readout->impedance;
    band.conductance = readout->bridgeConductance;
    band.muStatic = readout->bandMuStatic;
    band.muDynamic = readout->bandMuDynamic;
    band.upperEdge = player::kMeasuredUpperEdge;
    band.lowerEdge = player::kMeasuredLowerEdge;
    if (!band.valid())
        return;
    const player::DynamicsPath path;
    const int n = static_cast<int>(state.path.size());
    for (int k = 0; k < n; ++k)
    {
        const auto bow = player::musicalBow(path, band, k / (n - 1.0), value(ids::bowPressure), 1.0);
        state.path[static_cast<std::size_t>(k)] = {static_cast<float>(bow.beta),
                                                   static_cast<float>(bow.bowForce)};
    }
    state.pathPoints = n;
}

} // namespace rosin::plugin
