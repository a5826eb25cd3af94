// The plugin formats' factory: only the RosinPlugin target compiles this file (rosin_plugin_core must not
// define createPluginFilter, or the CLI and tests would need the plugin client's globals).
#include "instrument/plugin/RosinProcessor.h"

juce::AudioProcessor* JUCE_CALLTYPE createPluginFilter()
{
    return new rosin::plugin::RosinProcessor();
}
