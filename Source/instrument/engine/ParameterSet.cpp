#include "instrument/engine/ParameterSet.h"

namespace rosin::engine
{

ParameterSet::ParameterSet() : parameters_(makeParameters()) {}

juce::RangedAudioParameter* ParameterSet::find(const std::string& id) const noexcept
{
    const int i = parameterIndex(id);
    return i < 0 ? nullptr : parameters_[static_cast<std::size_t>(i)].get();
}

bool ParameterSet::set(const std::string& id, float plain, bool onlyIfChanged)
{
    juce::RangedAudioParameter* p = find(id);
    return p != nullptr && setPlainValue(*p, plain, onlyIfChanged);
}

RawParameterValues ParameterSet::raw() const noexcept
{
    // What juce::AudioProcessorValueTreeState keeps for each parameter: its value, denormalised again.
    RawParameterValues r;
    for (std::size_t i = 0; i < parameters_.size(); ++i)
        r.values[i] = parameters_[i]->convertFrom0to1(parameters_[i]->getValue());
    return r;
}

} // namespace rosin::engine
