#include "instrument/plugin/ParameterControls.h"

#include "instrument/plugin/HostParameters.h"

namespace rosin::plugin
{

ParameterControls::ParameterControls(juce::AudioProcessorValueTreeState& state) : state_(state)
{
    addSelector(ids::instrument, "Instrument");
    addSelector(ids::string, "String");
    addSelector(ids::friction, "Friction law");
    addAndMakeVisible(body_);
    body_.setTooltip("Instrument body at the bridge (off: rigid bridge)");
    bodyAttachment_ =
        std::make_unique<juce::AudioProcessorValueTreeState::ButtonAttachment>(state_, ids::body, body_);
    addAndMakeVisible(ear_);
    ear_.setTooltip(
        "Intonation by ear: the finger follows the pitch the string sounds (off: finger geometry)");
    earAttachment_ =
        std::make_unique<juce::AudioProcessorValueTreeState::ButtonAttachment>(state_, ids::intonation, ear_);
    addSelector(ids::output, "Output");
    addSelector(ids::quality, "Quality");
    addAndMakeVisible(dcBlocker_);
    dcBlocker_.setTooltip(
        "A 10 Hz high-pass on the bridge force and velocity outputs (the radiated sound has no "
        "DC)");
    dcBlockerAttachment_ = std::make_unique<juce::AudioProcessorValueTreeState::ButtonAttachment>(
        state_, ids::dcBlocker, dcBlocker_);

    addKnob(ids::bowForce, "Bow force", " N", 3);
    addKnob(ids::bowSpeed, "Bow speed", " m/s", 3);
    addKnob(ids::attackAcceleration, "Attack accel.", juce::String::fromUTF8(" m/s\xc2\xb2"), 2);
    addKnob(ids::beta, juce::String::fromUTF8("Bow position \xce\xb2"), "", 4);
    addKnob(ids::ambientTemperature, "Ambient",
            juce::String::fromUTF8(" \xc2\xb0"
                                   "C"),
            1);
    addKnob(ids::outputLevel, "Output level", " dB", 1);

    // The player: the mapping and the articulation, and the musical mapping's own controls.
    addSelector(ids::mapping, "Mapping");
    addSelector(ids::articulation, "Articulation");
    addKnob(ids::dynamics, "Dynamics", "", 2);
    addKnob(ids::bowPressure, "Bow pressure", "", 2);
    addKnob(ids::vibratoDepth, "Vibrato depth", " cents", 1);
    addKnob(ids::vibratoRate, "Vibrato rate", " Hz", 2);
    addKnob(ids::vibratoDelay, "Vibrato delay", " s", 2);
    addKnob(ids::slideTime, "Slide time", " s", 3);
    addKnob(ids::tremoloRate, "Tremolo rate", " Hz", 1);
}

ParameterControls::~ParameterControls() = default;

void ParameterControls::addKnob(const char* id, const juce::String& title, const juce::String& suffix,
                                int decimals)
{
    auto knob = std::make_unique<Knob>();
    knob->slider.setSliderStyle(juce::Slider::RotaryHorizontalVerticalDrag);
    knob->slider.setTextBoxStyle(juce::Slider::TextBoxBelow, false, 90, 20);
    knob->slider.setNumDecimalPlacesToDisplay(decimals);
    knob->slider.setTextValueSuffix(suffix);
    knob->label.setText(title, juce::dontSendNotification);
    knob->label.setJustificationType(juce::Justification::centred);
    knob->label.setFont(juce::Font(14.0f, juce::Font::bold));
    addAndMakeVisible(knob->slider);
    addAndMakeVisible(knob->label);
    // After the style settings: the attachment installs the parameter's range, skew and text conversion.
    knob->attachment =
        std::make_unique<juce::AudioProcessorValueTreeState::SliderAttachment>(state_, id, knob->slider);
    if (auto* p = state_.getParameter(id))
        knob->slider.setTooltip(p->getName(64));
    knobs_.push_back(std::move(knob));
}

void ParameterControls::addSelector(const char* id, const juce::String& title)
{
    auto selector = std::make_unique<Selector>();
    // The attachment maps item IDs 1..n to the choice indices, so items go in the parameter's order.
    if (auto* choice = dynamic_cast<juce::AudioParameterChoice*>(state_.getParameter(id)))
        selector->box.addItemList(choice->choices, 1);
    selector->label.setText(title, juce::dontSendNotification);
    selector->label.setJustificationType(juce::Justification::centredRight);
    selector->label.attachToComponent(&selector->box, true);
    addAndMakeVisible(selector->box);
    selector->attachment =
        std::make_unique<juce::AudioProcessorValueTreeState::ComboBoxAttachment>(state_, id, selector->box);
    selectors_.push_back(std::move(selector));
}

void ParameterControls::resized()
{
    auto area = getLocalBounds();
    auto row = area.removeFromTop(kSelectorRowHeight);
    // Selector widths: label (attached on the left) + box. The first three share the top row with the body
    // and ear switches; the output choice, its DC blocker and the quality take the second.
    // The third row: the player's mapping and articulation.
    const int labelWidths[] = {80, 56, 90, 60, 56, 80, 90};
    const int boxWidths[] = {100, 80, 140, 130, 70, 100, 110};
    for (std::size_t i = 0; i < selectors_.size(); ++i)
    {
        if (i == kPlayerSelectorsFrom)
            row = area.removeFromTop(kSelectorRowHeight);
        if (i == 3)
        {
            body_.setBounds(row.removeFromLeft(70));
            ear_.setBounds(row.removeFromLeft(150));
            row = area.removeFromTop(kSelectorRowHeight);
        }
        if (i == 4)
            dcBlocker_.setBounds(row.removeFromLeft(100));
        row.removeFromLeft(labelWidths[i]);
        selectors_[i]->box.setBounds(row.removeFromLeft(boxWidths[i]).reduced(0, 2));
        row.removeFromLeft(12);
    }

    area.removeFromTop(8);
    // Two rows of knobs: the bow and the instrument, then the musical mapping's.
    auto instrumentRow = area.removeFromTop(area.getHeight() / 2);
    const auto layRow = [this](juce::Rectangle<int> r, std::size_t from, std::size_t to)
    {
        const int width = r.getWidth() / juce::jmax(1, static_cast<int>(to - from));
        for (std::size_t i = from; i < to; ++i)
        {
            auto cell = r.removeFromLeft(width).reduced(4, 0);
            knobs_[i]->label.setBounds(cell.removeFromTop(20));
            knobs_[i]->slider.setBounds(cell);
        }
    };
    layRow(instrumentRow, 0, kPlayerKnobsFrom);
    layRow(area, kPlayerKnobsFrom, knobs_.size());
}

} // namespace rosin::plugin
