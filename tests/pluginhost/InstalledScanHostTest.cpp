// An installed Rosin found the way a DAW finds plugins: by scanning its plugin folders, not by a path handed
// to it. Run by tests/install, not by the normal suite: over $ROSIN_PLUGINHOST_SCAN_PATH (the
// staged DESTDIR folders) or, unset, over the formats' default locations (~/.vst3, /usr/lib/vst3, ~/.lv2,
// /usr/lib/lv2, ... after the Debian package is installed). The Rosin found must load, list its factory
// programs and play.
#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>
#include <stdexcept>

#include "pluginhost/HostHarness.h"

using namespace rosin::pluginhost;

namespace ROSIN_FILE_LOCAL
{

class InstalledPluginScan : public ::testing::TestWithParam<const char*>
{
  protected:
    juce::AudioPluginFormat& format() const
    {
        auto* f = rosin::pluginhost::format(GetParam());
        if (f == nullptr)
            throw std::runtime_error("format not registered");
        return *f;
    }

    juce::FileSearchPath searchPath() const
    {
        const char* scanPath = std::getenv("ROSIN_PLUGINHOST_SCAN_PATH");
        return scanPath != nullptr ? juce::FileSearchPath(scanPath) : format().getDefaultLocationsToSearch();
    }

    /// The scanner's identifiers that are Rosin: a bundle path for VST3, the plugin URI for LV2.
    juce::StringArray rosinIdentifiers(const juce::StringArray& found) const
    {
        juce::StringArray rosin;
        for (const auto& id : found)
            if (juce::String(GetParam()) == "VST3" ? id.endsWith("/Rosin.vst3") : id == ROSIN_LV2_URI)
                rosin.add(id);
        return rosin;
    }
};

TEST_P(InstalledPluginScan, FindsLoadsAndPlaysRosin)
{
    const auto path = searchPath();
    const auto found = format().searchPathsForPlugins(path, true, false);
    const auto rosin = rosinIdentifiers(found);
    ASSERT_EQ(rosin.size(), 1) << GetParam() << " scan of " << path.toString() << " found "
                               << found.joinIntoString(", ");
    juce::OwnedArray<juce::PluginDescription> descriptions;
    format().findAllTypesForFile(descriptions, rosin[0]);
    ASSERT_EQ(descriptions.size(), 1);
    const auto& desc = *descriptions[0];
    EXPECT_EQ(desc.name, "Rosin");
    EXPECT_TRUE(desc.isInstrument);
    std::cout << "[          ] " << GetParam() << " scan of " << path.toString() << " found " << rosin[0]
              << "\n";

    juce::String error;
    auto plugin = formats().createPluginInstance(desc, 48000.0, 512, error);
    ASSERT_NE(plugin, nullptr) << error;
    EXPECT_GE(plugin->getNumPrograms(), 8) << "the factory programs are missing";
    juce::StringArray programs;
    for (int i = 0; i < plugin->getNumPrograms(); ++i)
        programs.add(plugin->getProgramName(i));
    EXPECT_TRUE(programs.contains("cello-plastic") && programs.contains("violin-thermal"))
        << programs.joinIntoString(", ");
    prepare(*plugin, 48000.0, 512);
    const Render r = render(*plugin, notePlan(48000.0, {512}));
    EXPECT_EQ(r.nonFinite, 0);
    EXPECT_GT(r.rmsDuringNote, kSilenceRms) << "silent";
    plugin->releaseResources();
    destroy(plugin);
}

INSTANTIATE_TEST_SUITE_P(Installed, InstalledPluginScan, ::testing::Values("VST3", "LV2"),
                         [](const auto& info) { return std::string(info.param); });

} // namespace ROSIN_FILE_LOCAL
