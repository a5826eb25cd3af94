#include "instrument/plugin/StringLane.h"

#include <cmath>

#include <juce_audio_basics/juce_audio_basics.h>

namespace rosin::plugin
{

namespace
{
const char* const kRomanFromOne[] = {"", "I", "II", "III", "IV", "V", "VI", "VII", "VIII"};
// Temperature bar scale: the thermal laws' contact rises stay below about 100 K when played.
constexpr float kTemperatureFullScale = 100.0f;

juce::String noteName(float hz)
{
    if (!(hz > 0.0f))
        return "-";
    const int note = static_cast<int>(std::lround(69.0 + 12.0 * std::log2(hz / 440.0)));
    return juce::MidiMessage::getMidiNoteName(note, true, true, 4);
}
} // namespace

StringLane::StringLane(int romanIndex) : roman_(juce::jlimit(1, 8, romanIndex)) {}

void StringLane::setReadout(const StringReadout& readout, bool present)
{
    readout_ = readout;
    present_ = present;
    repaint();
}

juce::Colour StringLane::regimeColour(Regime regime)
{
    switch (regime)
    {
    case Regime::Helmholtz:
        return juce::Colour(0xff4caf50);
    case Regime::SMotion:
        return juce::Colour(0xff8bc34a);
    case Regime::DoubleSlipping:
    case Regime::MultipleSlipping:
        return juce::Colour(0xffffb300);
    case Regime::AnomalousLowFrequency:
        return juce::Colour(0xff7e57c2);
    case Regime::Raucous:
        return juce::Colour(0xffe53935);
    case Regime::ConstantSlipping:
    case Regime::NoSlip:
        break;
    }
    return juce::Colour(0xff607d8b);
}

void StringLane::paint(juce::Graphics& g)
{
    const auto& lf = getLookAndFeel();
    const auto text = lf.findColour(juce::Label::textColourId);
    auto bounds = getLocalBounds().toFloat().reduced(2.0f);
    g.setColour(lf.findColour(juce::ResizableWindow::backgroundColourId).brighter(0.08f));
    g.fillRoundedRectangle(bounds, 6.0f);
    if (!present_)
    {
        g.setColour(text.withAlpha(0.3f));
        g.drawText(juce::String(kRomanFromOne[roman_]) + "  (no string)", bounds.reduced(10.0f, 0.0f),
                   juce::Justification::centredLeft);
        return;
    }
    const auto& r = readout_;
    const float dim = r.bowing ? 1.0f : 0.55f;
    auto area = bounds.reduced(10.0f, 6.0f);

    // Identity: string number, open pitch, sounding note.
    auto id = area.removeFromLeft(84.0f);
    g.setColour(text.withAlpha(dim));
    g.setFont(juce::Font(20.0f, juce::Font::bold));
    g.drawText(kRomanFromOne[roman_], id.removeFromTop(id.getHeight() * 0.55f),
               juce::Justification::centredLeft);
    g.setFont(juce::Font(12.5f));
    const bool open = std::abs(r.frequency / juce::jmax(1.0f, r.openFrequency) - 1.0f) < 0.01f;
    g.drawText(open ? noteName(r.openFrequency) + " open"
                    : noteName(r.openFrequency) + juce::String::fromUTF8(" \xe2\x86\x92 ") +
                          noteName(r.frequency),
               id, juce::Justification::centredLeft);

    // Contact temperature: number and a bar.
    auto temp = area.removeFromLeft(120.0f);
    g.setFont(juce::Font(12.0f));
    g.setColour(text.withAlpha(0.7f * dim));
    g.drawText("contact", temp.removeFromTop(14.0f), juce::Justification::centredLeft);
    g.setFont(juce::Font(16.0f, juce::Font::bold));
    g.setColour(text.withAlpha(dim));
    g.drawText("+" + juce::String(r.temperature, 1) + " K", temp.removeFromTop(20.0f),
               juce::Justification::centredLeft);
    auto bar = temp.removeFromTop(8.0f).withWidth(100.0f);
    g.setColour(text.withAlpha(0.15f));
    g.fillRoundedRectangle(bar, 3.0f);
    const float fill = juce::jlimit(0.0f, 1.0f, r.temperature / kTemperatureFullScale);
    g.setColour(juce::Colour(0xffff7043).withAlpha(dim));
    g.fillRoundedRectangle(bar.withWidth(bar.getWidth() * fill), 3.0f);

    // Stick / slip: the state at the end of the last block, the share of time stuck, the slips per period.
    auto stick = area.removeFromLeft(100.0f);
    const float row = stick.getHeight() / 3.0f;
    auto led = stick.removeFromTop(row + 4.0f);
    auto dot = led.removeFromLeft(16.0f).withSizeKeepingCentre(12.0f, 12.0f);
    const bool active = r.bowing && r.stickFraction < 0.999f;
    g.setColour(!active ? text.withAlpha(0.2f)
                        : (r.sticking ? juce::Colour(0xff42a5f5) : juce::Colour(0xffffa726)));
    g.fillEllipse(dot);
    g.setColour(text.withAlpha(dim));
    g.setFont(juce::Font(14.0f, juce::Font::bold));
    g.drawText(!r.bowing ? "free" : (r.sticking ? "stick" : "slip"), led.withTrimmedLeft(4.0f),
               juce::Justification::centredLeft);
    g.setFont(juce::Font(12.0f));
    g.setColour(text.withAlpha(0.7f * dim));
    if (r.bowing)
        g.drawText("stuck " + juce::String(juce::roundToInt(100.0f * r.stickFraction)) + " %",
                   stick.removeFromTop(row - 2.0f), juce::Justification::centredLeft);
    if (r.bowing)
        g.drawText(juce::String(r.slipsPerPeriod, 2) + " slips/T", stick, juce::Justification::centredLeft);

    // Regime: a coloured tag and the statistics behind it.
    auto regime = area;
    auto tag = regime.removeFromTop(regime.getHeight() * 0.55f).reduced(0.0f, 3.0f);
    const auto colour = r.bowing ? regimeColour(r.regime) : regimeColour(Regime::NoSlip);
    g.setColour(colour.withAlpha(0.85f));
    g.fillRoundedRectangle(tag.withWidth(juce::jmin(tag.getWidth(), 150.0f)), 5.0f);
    g.setColour(juce::Colours::white);
    g.setFont(juce::Font(14.0f, juce::Font::bold));
    g.drawText(regimeDisplayName(r.regime, r.bowing), tag.withWidth(juce::jmin(tag.getWidth(), 150.0f)),
               juce::Justification::centred);
    g.setFont(juce::Font(12.0f));
    g.setColour(text.withAlpha(0.75f * dim));
    if (r.bowing)
        g.drawText(juce::String(r.flybacksPerPeriod, 2) + " flybacks/T   CV " +
                       juce::String(r.irregularity, 2),
                   regime, juce::Justification::centredLeft);
}

} // namespace rosin::plugin
