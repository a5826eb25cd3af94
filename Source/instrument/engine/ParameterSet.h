#pragma once
// The parameters of an instrument played without a host (the offline render): the same JUCE parameter
// objects the plugin hands its host (makeParameters()), set and read as a host and JUCE's value tree state
// set and read them, so a render here plays exactly the values the plugin would.
#include <memory>
#include <string>
#include <vector>

#include "instrument/engine/EngineParameters.h"

namespace rosin::engine
{

class ParameterSet
{
  public:
    ParameterSet();

    /// The parameter of `id`, or null.
    juce::RangedAudioParameter* find(const std::string& id) const noexcept;
    /// Sets `id` to its plain value `plain` as a user's move does (setPlainValue); false if there is no such
    /// parameter or, with `onlyIfChanged`, its value was already that.
    bool set(const std::string& id, float plain, bool onlyIfChanged = false);
    /// The raw values a host's value tree state would hold now (each parameter's value, denormalised).
    RawParameterValues raw() const noexcept;

  private:
    std::vector<std::unique_ptr<juce::RangedAudioParameter>> parameters_; ///< in the table's order
};

} // namespace rosin::engine
