#pragma once
// The LV2 wrapper of Debian's JUCE 7.0.5 (juce_LV2_Client.cpp, LV2PluginInstance::retrieve) restores a state
// by decoding its string with MemoryBlock::fromBase64Encoding, which sizes its buffer from the decimal count
// before the '.' unchecked: a damaged count ("-1.", "-2147483648.", "99999999999999999999.") makes it throw
// std::bad_alloc inside the host, before the plugin's setStateInformation sees a byte. Lv2StateGuard.cpp
// checks the string with damagedStateString() first and refuses it, the plugin left as it was.
#include <cstddef>
#include <optional>
#include <string>

namespace rosin::plugin
{

/// Why `text` (`size` bytes, a trailing NUL allowed) is not a state string JUCE's decoder can take safely:
/// its count is not a decimal number of at most `maxBytes`, its payload holds a character outside JUCE's
/// base-64 alphabet, or the payload's length does not encode exactly that many bytes (JUCE writes
/// ceil(8 count / 6) characters). Nothing when it is well formed.
std::optional<std::string> damagedStateString(const char* text, std::size_t size, std::size_t maxBytes);

} // namespace rosin::plugin
