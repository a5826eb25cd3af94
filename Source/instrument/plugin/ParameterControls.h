#pragma once
// The host parameters as controls: the model selectors (instrument, string, friction law, body, intonation)
// on one row, the output, its DC blocker and the quality on a second, and the gesture knobs in physical
// units below, each attached to its APVTS parameter.
#include <memory>
#include <vector>

#include <juce_audio_processors/juce_audio_processors.h>
#include <juce_gui_basics/juce_gui_basics.h>

namespace rosin::plugin
{

class ParameterControls : public juce::Component
{
  public:
    explicit ParameterControls(juce::AudioProcessorValueTreeState& state);
    ~ParameterControls() override;

    void resized() override;

    static constexpr int kSelectorRowHeight = 28;
    /// Where the second row's own controls end: the editor puts the body response's buttons after it.
    static constexpr int kSecondRowWidth = 440;

  private:
    static constexpr std::size_t kPlayerSelectorsFrom = 5; ///< mapping, articulation: the third row
    static constexpr std::size_t kPlayerKnobsFrom = 6;     ///< the musical mapping's knobs: the second row
    struct Knob
    {
        juce::Slider slider;
        juce::Label label;
        std::unique_ptr<juce::AudioProcessorValueTreeState::SliderAttachment> attachment;
    };
    struct Selector
    {
        juce::ComboBox box;
        juce::Label label;
        std::unique_ptr<juce::AudioProcessorValueTreeState::ComboBoxAttachment> attachment;
    };

    void addKnob(const char* id, const juce::String& title, const juce::String& suffix, int decimals);
    void addSelector(const char* id, const juce::String& title);

    juce::AudioProcessorValueTreeState& state_;
    std::vector<std::unique_ptr<Knob>> knobs_;
    std::vector<std::unique_ptr<Selector>> selectors_;
    juce::ToggleButton body_{"Body"};
    std::unique_ptr<juce::AudioProcessorValueTreeState::ButtonAttachment> bodyAttachment_;
    juce::ToggleButton ear_{"Intonation by ear"};
    std::unique_ptr<juce::AudioProcessorValueTreeState::ButtonAttachment> earAttachment_;
    juce::ToggleButton dcBlocker_{"DC blocker"};
    std::unique_ptr<juce::AudioProcessorValueTreeState::ButtonAttachment> dcBlockerAttachment_;
};

} // namespace rosin::plugin
