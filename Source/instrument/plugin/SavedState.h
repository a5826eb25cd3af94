#pragma once
// A saved plugin state read defensively: a project file is user input. Its bytes are
// checked before any parsing (size, XML nesting depth: JUCE's XmlDocument recurses per element and grows
// attribute strings quadratically), every restored parameter value is checked against its range, and after
// the restore every parameter the host sees is refreshed, also when the value did not change inside (item 8).
#include <juce_audio_processors/juce_audio_processors.h>

#include <optional>
#include <string>
#include <vector>

namespace rosin::plugin
{

/// Largest state accepted, bytes: a state is ~1 kB; 64 kB bounds JUCE's quadratic attribute parsing to
/// milliseconds.
inline constexpr int kMaxStateBytes = 64 * 1024;
/// Deepest XML nesting accepted: a state is three levels deep.
inline constexpr int kMaxStateDepth = 16;

/// Why these bytes are not parsed (too large, too deeply nested), or nothing.
std::optional<std::string> unparseableState(const void* data, int sizeInBytes);

/// Replaces every PARAM value of `tree` that is not a finite number inside its parameter's range by the
/// parameter's default. Returns one message per replaced value, naming the parameter, what was found and
/// what was expected.
std::vector<std::string> sanitiseParameterValues(juce::ValueTree& tree,
                                                 juce::AudioProcessorValueTreeState& state);

/// Sends every parameter's value to the host (setValueNotifyingHost), also where it did not change inside:
/// a switch the host had set to 0.59 reads as "on", a restored "on" changes nothing inside, and the host's
/// copy would stay 0.59 (pluginval's state check; JUCE's LV2 host learns values only this way).
void refreshHostValues(juce::AudioProcessorValueTreeState& state);

} // namespace rosin::plugin
