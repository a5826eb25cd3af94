// The LV2 module's entry point: JUCE's descriptor (its lv2_descriptor is compiled as juce_lv2_descriptor,
// Source/instrument/plugin/CMakeLists.txt) with one change, a state interface whose restore checks the state
// string before JUCE decodes it (Lv2StateCheck.h): a damaged one is refused with a message on stderr, the
// plugin left as it was, instead of std::bad_alloc taking the host down. The plugin's handle stays JUCE's own
// (its editor reaches the instance through it), so the state keys' URIDs are kept per handle here.
#include <cstdint>
#include <cstring>
#include <iostream>
#include <map>
#include <mutex>
#include <string>

#include <lv2/atom/atom.h>
#include <lv2/core/lv2.h>
#include <lv2/state/state.h>
#include <lv2/urid/urid.h>

#include "instrument/plugin/Lv2StateCheck.h"
#include "instrument/plugin/SavedState.h"

extern "C" __attribute__((visibility("hidden"))) const LV2_Descriptor* juce_lv2_descriptor(uint32_t index);

namespace
{

/// The URIDs JUCE's restore reads, as this instance's host maps them.
struct StateKeys
{
    LV2_URID state = 0, program = 0, atomString = 0, atomInt = 0;
};

std::mutex keysMutex;
std::map<LV2_Handle, StateKeys> keysByInstance; // instantiate, cleanup and restore run off the audio thread

const LV2_Descriptor& juceDescriptor()
{
    static const LV2_Descriptor* d = juce_lv2_descriptor(0);
    return *d;
}

const LV2_State_Interface& juceState()
{
    static const auto* s =
        static_cast<const LV2_State_Interface*>(juceDescriptor().extension_data(LV2_STATE__interface));
    return *s;
}

LV2_Handle instantiate(const LV2_Descriptor* descriptor, double rate, const char* bundle,
                       const LV2_Feature* const* features)
{
    LV2_Handle handle = juceDescriptor().instantiate(&juceDescriptor(), rate, bundle, features);
    if (handle == nullptr || features == nullptr)
        return handle;
    for (auto f = features; *f != nullptr; ++f)
        if (std::strcmp((*f)->URI, LV2_URID__map) == 0)
        {
            const auto* map = static_cast<const LV2_URID_Map*>((*f)->data);
            const std::string uri = descriptor->URI;
            const StateKeys keys{map->map(map->handle, (uri + ":StateString").c_str()),
                                 map->map(map->handle, (uri + ":Program").c_str()),
                                 map->map(map->handle, LV2_ATOM__String),
                                 map->map(map->handle, LV2_ATOM__Int)};
            std::lock_guard<std::mutex> lock(keysMutex);
            keysByInstance[handle] = keys;
        }
    return handle;
}

void cleanup(LV2_Handle handle)
{
    {
        std::lock_guard<std::mutex> lock(keysMutex);
        keysByInstance.erase(handle);
    }
    juceDescriptor().cleanup(handle);
}

/// JUCE's restore reads a program index first and the state string only without one; the string is checked
/// here on the same terms.
LV2_State_Status restore(LV2_Handle handle, LV2_State_Retrieve_Function retrieve, LV2_State_Handle state,
                         uint32_t flags, const LV2_Feature* const* features)
{
    StateKeys keys;
    {
        std::lock_guard<std::mutex> lock(keysMutex);
        if (const auto it = keysByInstance.find(handle); it != keysByInstance.end())
            keys = it->second;
    }
    std::size_t size = 0;
    uint32_t type = 0, valueFlags = 0;
    const void* program = retrieve(state, keys.program, &size, &type, &valueFlags);
    const bool isProgram = program != nullptr && type == keys.atomInt && size == sizeof(int32_t);
    const void* text = isProgram ? nullptr : retrieve(state, keys.state, &size, &type, &valueFlags);
    if (text != nullptr && type == keys.atomString)
        if (const auto why =
                rosin::plugin::damagedStateString(static_cast<const char*>(text), size,
                                                  static_cast<std::size_t>(rosin::plugin::kMaxStateBytes)))
        {
            std::cerr << "rosin: LV2 state not restored: " << *why << "\n";
            return LV2_STATE_ERR_UNKNOWN;
        }
    return juceState().restore(handle, retrieve, state, flags, features);
}

const void* extensionData(const char* uri)
{
    static const LV2_State_Interface guarded{juceState().save, restore};
    if (std::strcmp(uri, LV2_STATE__interface) == 0)
        return &guarded;
    return juceDescriptor().extension_data(uri);
}

} // namespace

extern "C" LV2_SYMBOL_EXPORT const LV2_Descriptor* lv2_descriptor(uint32_t index)
{
    if (index != 0)
        return nullptr;
    static const LV2_Descriptor guarded{juceDescriptor().URI,
                                        instantiate,
                                        juceDescriptor().connect_port,
                                        juceDescriptor().activate,
                                        juceDescriptor().run,
                                        juceDescriptor().deactivate,
                                        cleanup,
                                        extensionData};
    return &guarded;
}
