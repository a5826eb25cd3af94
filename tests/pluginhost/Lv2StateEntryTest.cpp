// The LV2 module's state interface reached as any LV2 host reaches it: dlopen the built libRosin.so, take
// lv2_descriptor(0), instantiate it with a URID map, the bounded-block-length feature and the maximum block
// length (what JUCE's wrapper requires), and call the state interface's save and restore with the host's
// callbacks. A state string whose byte count is damaged ("-1.", "-2147483648.", "99999999999999999999.", huge
// or negative) made JUCE's decoder throw std::bad_alloc from inside restore and took the host down; it must
// be refused with an error status and leave the plugin's state as it was, and a good state still restores.
#include <gtest/gtest.h>

#include <dlfcn.h>

#include <cstring>
#include <map>
#include <string>
#include <vector>

#include <juce_audio_processors/juce_audio_processors.h>

#include <lv2/atom/atom.h>
#include <lv2/buf-size/buf-size.h>
#include <lv2/core/lv2.h>
#include <lv2/options/options.h>
#include <lv2/state/state.h>
#include <lv2/urid/urid.h>

namespace
{

/// The host's side: URIDs, the features, and one stored state property.
struct BareHost
{
    std::map<std::string, LV2_URID> ids;
    LV2_URID_Map map{this,
                     [](LV2_URID_Map_Handle h, const char* uri) -> LV2_URID
                     {
                         auto& ids = static_cast<BareHost*>(h)->ids;
                         const auto [it, added] = ids.emplace(uri, static_cast<LV2_URID>(ids.size() + 1));
                         return it->second;
                     }};
    int32_t maxBlock = 512;
    std::vector<LV2_Options_Option> options;
    LV2_Feature mapFeature{LV2_URID__map, &map};
    LV2_Feature bounded{LV2_BUF_SIZE__boundedBlockLength, nullptr};
    LV2_Feature optionsFeature{LV2_OPTIONS__options, nullptr};
    std::vector<const LV2_Feature*> features;
    // The stored property (what save wrote, or what a damaged project file holds).
    LV2_URID key = 0, type = 0;
    std::string value;

    BareHost()
    {
        options = {{LV2_OPTIONS_INSTANCE, 0, urid(LV2_BUF_SIZE__maxBlockLength), sizeof(int32_t),
                    urid(LV2_ATOM__Int), &maxBlock},
                   {LV2_OPTIONS_INSTANCE, 0, 0, 0, 0, nullptr}};
        optionsFeature.data = options.data();
        features = {&mapFeature, &bounded, &optionsFeature, nullptr};
    }
    LV2_URID urid(const char* uri) { return map.map(this, uri); }

    static LV2_State_Status store(LV2_State_Handle h, uint32_t key, const void* value, size_t size,
                                  uint32_t type, uint32_t)
    {
        auto* host = static_cast<BareHost*>(h);
        host->key = key;
        host->type = type;
        host->value.assign(static_cast<const char*>(value), size);
        return LV2_STATE_SUCCESS;
    }
    static const void* retrieve(LV2_State_Handle h, uint32_t key, size_t* size, uint32_t* type,
                                uint32_t* flags)
    {
        auto* host = static_cast<BareHost*>(h);
        if (key != host->key)
            return nullptr;
        *size = host->value.size();
        *type = host->type;
        *flags = LV2_STATE_IS_POD | LV2_STATE_IS_PORTABLE;
        return host->value.data();
    }
};

class Lv2StateEntry : public ::testing::Test
{
  protected:
    void SetUp() override
    {
        const std::string path = std::string(ROSIN_LV2_BUNDLE_DIR) + "/libRosin.so";
        library = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        ASSERT_NE(library, nullptr) << dlerror();
        auto entry = reinterpret_cast<LV2_Descriptor_Function>(dlsym(library, "lv2_descriptor"));
        ASSERT_NE(entry, nullptr);
        descriptor = entry(0);
        ASSERT_NE(descriptor, nullptr);
        EXPECT_STREQ(descriptor->URI, ROSIN_LV2_URI);
        instance = descriptor->instantiate(descriptor, 48000.0, ROSIN_LV2_BUNDLE_DIR, host.features.data());
        ASSERT_NE(instance, nullptr);
        state = static_cast<const LV2_State_Interface*>(descriptor->extension_data(LV2_STATE__interface));
        ASSERT_NE(state, nullptr);
    }
    void TearDown() override
    {
        if (instance != nullptr)
            descriptor->cleanup(instance);
        // The module stays loaded: JUCE's message thread inside it outlives an instance.
    }
    std::string saved()
    {
        EXPECT_EQ(state->save(instance, BareHost::store, &host, 0, host.features.data()), LV2_STATE_SUCCESS);
        return host.value;
    }
    LV2_State_Status restoreText(const std::string& text)
    {
        host.key = host.urid((std::string(ROSIN_LV2_URI) + ":StateString").c_str());
        host.type = host.urid(LV2_ATOM__String);
        host.value = text + '\0';
        return state->restore(instance, BareHost::retrieve, &host, 0, host.features.data());
    }

    BareHost host;
    void* library = nullptr;
    const LV2_Descriptor* descriptor = nullptr;
    LV2_Handle instance = nullptr;
    const LV2_State_Interface* state = nullptr;
};

TEST_F(Lv2StateEntry, ADamagedByteCountIsRefusedAndChangesNothing)
{
    const std::string before = saved();
    ASSERT_NE(before.find('.'), std::string::npos) << before;
    const std::string payload = before.substr(before.find('.'), before.size() - before.find('.') - 1);
    for (const std::string count :
         {"-1", "-2147483648", "99999999999999999999", "2147483647", "4294967295", "-99999999999", "1000000"})
    {
        EXPECT_NE(restoreText(count + payload), LV2_STATE_SUCCESS) << count;
        EXPECT_EQ(saved(), before) << "after " << count;
    }
}

// A good state still restores, and is taken: the saved state with the bow force changed in its XML comes
// back from the next save with that force (a restore that did nothing would give the old one back).
TEST_F(Lv2StateEntry, AGoodStateStillRestores)
{
    const std::string before = saved();
    juce::MemoryBlock binary;
    ASSERT_TRUE(binary.fromBase64Encoding(before.c_str()));
    auto xml = juce::AudioProcessor::getXmlFromBinary(binary.getData(), static_cast<int>(binary.getSize()));
    ASSERT_NE(xml, nullptr);
    juce::XmlElement* force = nullptr;
    for (auto* p : xml->getChildWithTagNameIterator("PARAM"))
        if (p->getStringAttribute("id") == "bowForce")
            force = p;
    ASSERT_NE(force, nullptr) << xml->toString();
    ASSERT_NE(force->getDoubleAttribute("value"), 2.5);
    force->setAttribute("value", 2.5);
    juce::MemoryBlock changed;
    juce::AudioProcessor::copyXmlToBinary(*xml, changed);
    EXPECT_EQ(restoreText(changed.toBase64Encoding().toStdString()), LV2_STATE_SUCCESS);

    const std::string after = saved();
    juce::MemoryBlock restored;
    ASSERT_TRUE(restored.fromBase64Encoding(after.c_str()));
    const auto back =
        juce::AudioProcessor::getXmlFromBinary(restored.getData(), static_cast<int>(restored.getSize()));
    ASSERT_NE(back, nullptr);
    double restoredForce = 0.0;
    for (auto* p : back->getChildWithTagNameIterator("PARAM"))
        if (p->getStringAttribute("id") == "bowForce")
            restoredForce = p->getDoubleAttribute("value");
    EXPECT_NEAR(restoredForce, 2.5, 1e-4); // through the parameter's normalised float (default 1 N)
}

} // namespace
