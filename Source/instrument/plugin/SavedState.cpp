// Defensive reading of saved plugin states (SavedState.h).
#include "instrument/plugin/SavedState.h"

#include <cmath>

namespace rosin::plugin
{

std::optional<std::string> unparseableState(const void* data, int sizeInBytes)
{
    if (sizeInBytes > kMaxStateBytes)
        return "state of " + std::to_string(sizeInBytes) + " bytes; expected at most " +
               std::to_string(kMaxStateBytes);
    // Nesting: count '<name' as one level down, '</' and '/>' as one up; comments and declarations do not
    // nest. Attribute values cannot hold a raw '<' in well-formed XML, so this bounds what the parser sees.
    const auto* bytes = static_cast<const char*>(data);
    int depth = 0;
    for (int i = 0; i + 1 < sizeInBytes; ++i)
    {
        if (bytes[i] == '<')
        {
            const char next = bytes[i + 1];
            if (next == '/')
                --depth;
            else if (next != '?' && next != '!')
                ++depth;
        }
        else if (bytes[i] == '/' && bytes[i + 1] == '>')
            --depth;
        if (depth > kMaxStateDepth)
            return "XML nested deeper than " + std::to_string(kMaxStateDepth) + " levels";
    }
    return std::nullopt;
}

std::vector<std::string> sanitiseParameterValues(juce::ValueTree& tree,
                                                 juce::AudioProcessorValueTreeState& state)
{
    std::vector<std::string> messages;
    for (auto child : tree)
    {
        if (!child.hasType("PARAM"))
            continue;
        const juce::String id = child.getProperty("id").toString();
        auto* parameter = state.getParameter(id);
        if (parameter == nullptr)
            continue; // unknown ids are ignored by replaceState
        const auto& range = parameter->getNormalisableRange();
        const juce::var& stored = child.getProperty("value");
        const double value =
            stored.isString() ? stored.toString().getDoubleValue() : static_cast<double>(stored);
        const bool number = stored.isDouble() || stored.isInt() || stored.isInt64() || stored.isBool() ||
                            (stored.isString() && stored.toString().trim().containsOnly("0123456789+-.eE"));
        if (number && std::isfinite(value) && value >= range.start && value <= range.end)
            continue;
        const float fallback = range.convertFrom0to1(parameter->getDefaultValue());
        messages.push_back("parameter \"" + id.toStdString() + "\": expected a number in " +
                           std::to_string(range.start) + ".." + std::to_string(range.end) + " but got \"" +
                           stored.toString().toStdString() + "\"; using the default " +
                           std::to_string(fallback));
        child.setProperty("value", fallback, nullptr);
    }
    return messages;
}

void refreshHostValues(juce::AudioProcessorValueTreeState& state)
{
    for (auto* p : state.processor.getParameters())
    {
        auto* parameter = dynamic_cast<juce::RangedAudioParameter*>(p);
        if (parameter == nullptr)
            continue;
        const auto* raw = state.getRawParameterValue(parameter->getParameterID());
        if (raw == nullptr)
            continue;
        // Sent even when the value inside did not change: a host that set a switch to 0.59 holds 0.59 while
        // the plugin holds "on", and the LV2 host learns values only from the plugin's notifications.
        parameter->setValueNotifyingHost(parameter->convertTo0to1(raw->load()));
    }
}

} // namespace rosin::plugin
