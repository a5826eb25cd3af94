#pragma once
// One string's live readouts: which string and note, contact temperature, stick/slip, and the regime with
// the flyback statistics it was judged from. Painted from a StringReadout the editor hands it (no timers).
#include <juce_gui_basics/juce_gui_basics.h>

#include "instrument/plugin/StringTelemetry.h"

namespace rosin::plugin
{

class StringLane : public juce::Component
{
  public:
    /// romanIndex: 1 = string I (the highest), as players number them.
    explicit StringLane(int romanIndex);

    void setReadout(const StringReadout& readout, bool present);
    void paint(juce::Graphics& g) override;

    static juce::Colour regimeColour(Regime regime);

  private:
    int roman_;
    StringReadout readout_;
    bool present_ = false;
};

} // namespace rosin::plugin
