#include "instrument/plugin/HostParameters.h"

namespace rosin::plugin
{

juce::AudioProcessorValueTreeState::ParameterLayout createParameterLayout()
{
    auto parameters = engine::makeParameters();
    juce::AudioProcessorValueTreeState::ParameterLayout layout;
    layout.add(parameters.begin(), parameters.end());
    return layout;
}

ParameterReader::ParameterReader(juce::AudioProcessorValueTreeState& state)
{
    for (std::size_t i = 0; i < values_.size(); ++i)
    {
        values_[i] = state.getRawParameterValue(engine::allParameterIds()[i]);
        jassert(values_[i] != nullptr);
    }
}

engine::RawParameterValues ParameterReader::load() const noexcept
{
    engine::RawParameterValues raw;
    for (std::size_t i = 0; i < values_.size(); ++i)
        raw.values[i] = values_[i]->load();
    return raw;
}

} // namespace rosin::plugin
