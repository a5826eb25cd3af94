// A program from a file (what fit_body.py writes for a player's own instrument) in the plugin: it plays what
// `rosin render --midi --preset FILE.json` plays (the offline render of the same file, sample for sample), it
// survives a reload of the project after the file is gone (the state keeps its text), a broken file is
// refused naming the file and the field and leaves the program playing, and a factory program replaces it.
#include <gtest/gtest.h>

#include "core/config/JsonFile.h"
#include "core/config/PresetLoader.h"
#include "instrument/engine/OfflineInstrument.h"
#include "instrument/plugin/PluginTestSupport.h"
#include "instrument/plugin/SavedState.h"

namespace rosin::test
{
namespace ROSIN_FILE_LOCAL
{

/// The default program with a radiation calibration, as fit_body.py writes it: -8 dB below 400 Hz, +8 dB
/// above 1.6 kHz (large enough to hear, inside the field's +-30 dB).
juce::File writeFittedProgram(const juce::File& folder, const std::string& gains, int indent = 2)
{
    nlohmann::json j = config::readJsonFile(config::resolvePresetPath(engine::kDefaultProgramName));
    j["name"] = "my-cello";
    j["radiationGains"] = nlohmann::json::parse(gains);
    const juce::File file = folder.getChildFile("my-cello.json");
    file.replaceWithText(j.dump(indent));
    return file;
}

const char* kGains = R"([{"hz": 400, "db": -8}, {"hz": 1600, "db": 8}])";

juce::MidiMessageSequence heldNote()
{
    juce::MidiMessageSequence seq;
    seq.addEvent(juce::MidiMessage::noteOn(1, 50, static_cast<juce::uint8>(80)), 0.0);
    seq.addEvent(juce::MidiMessage::noteOff(1, 50), 0.5);
    return seq;
}

engine::MidiRenderSettings settings()
{
    engine::MidiRenderSettings s;
    s.sampleRate = 48000.0;
    s.blockSize = 480;
    s.tailSeconds = 0.1;
    return s;
}

std::vector<float> play(plugin::RosinProcessor& p)
{
    return renderMidi(p, heldNote(), settings()).audio;
}

double rmsDifference(const std::vector<float>& a, const std::vector<float>& b)
{
    double sum = 0.0;
    for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i)
        sum += (a[i] - b[i]) * (a[i] - b[i]);
    return std::sqrt(sum / static_cast<double>(std::max<std::size_t>(1, std::min(a.size(), b.size()))));
}

TEST(PluginProgramFile, PlaysWhatTheOfflineRenderOfTheFilePlays)
{
    TempFolder temp;
    const juce::File file = writeFittedProgram(temp.folder(), kGains);
    plugin::RosinProcessor processor;
    ASSERT_TRUE(processor.loadProgramFile(file)) << processor.programFileStatus();
    EXPECT_TRUE(processor.programTitle().startsWith("my-cello")) << processor.programTitle();
    const std::vector<float> host = play(processor);

    engine::OfflineInstrument offline;
    const config::Preset preset = config::loadPreset(file.getFullPathName().toStdString());
    offline.setProgram({preset.name, preset});
    const std::vector<float> own = offline.render(heldNote(), settings()).audio;
    ASSERT_EQ(host.size(), own.size());
    EXPECT_EQ(rmsDifference(host, own), 0.0);

    // The calibration is heard: the factory program it was made from sounds different (not a no-op load).
    plugin::RosinProcessor factory;
    const std::vector<float> plain = play(factory);
    const double level = rmsDifference(plain, std::vector<float>(plain.size(), 0.0f));
    ASSERT_GT(level, 1e-3);
    EXPECT_GT(rmsDifference(host, plain), 0.1 * level);
}

TEST(PluginProgramFile, SurvivesAReloadAfterTheFileIsGone)
{
    TempFolder temp;
    const juce::File file = writeFittedProgram(temp.folder(), kGains);
    plugin::RosinProcessor first;
    ASSERT_TRUE(first.loadProgramFile(file)) << first.programFileStatus();
    juce::MemoryBlock state;
    first.getStateInformation(state);
    const std::vector<float> before = play(first);
    ASSERT_TRUE(file.deleteFile());

    plugin::RosinProcessor reopened;
    reopened.setStateInformation(state.getData(), static_cast<int>(state.getSize()));
    EXPECT_TRUE(reopened.programTitle().startsWith("my-cello")) << reopened.programTitle();
    EXPECT_EQ(rmsDifference(play(reopened), before), 0.0);

    // Choosing a factory program ends the file's program, in the state too.
    reopened.setCurrentProgram(reopened.getCurrentProgram());
    juce::MemoryBlock factoryState;
    reopened.getStateInformation(factoryState);
    EXPECT_FALSE(factoryState.toString().contains("programFileText"));
}

// The file's text goes into the state in an XML attribute, where every quote grows to six characters: the
// largest program file accepted, written as compact JSON, the densest in quotes, must still give a state the
// plugin restores (a state is refused beyond kMaxStateBytes).
TEST(PluginProgramFile, TheLargestAcceptedFileStillReloads)
{
    TempFolder temp;
    nlohmann::json gains = nlohmann::json::array();
    const juce::File file = temp.folder().getChildFile("many-gains.json");
    for (int i = 0;; ++i)
    {
        gains.push_back({{"hz", 20 + i}, {"db", 0}});
        writeFittedProgram(temp.folder(), gains.dump(), -1).moveFileTo(file);
        if (file.getSize() > plugin::kMaxProgramFileBytes)
        {
            gains.erase(gains.end() - 1);
            writeFittedProgram(temp.folder(), gains.dump(), -1).moveFileTo(file);
            break;
        }
    }
    ASSERT_GT(file.getSize(), plugin::kMaxProgramFileBytes - 200);
    {
        plugin::RosinProcessor refusing; // one gain more is refused, with the size and the limit
        nlohmann::json more = gains;
        more.push_back({{"hz", 20 + static_cast<int>(gains.size())}, {"db", 0}});
        const juce::File big = writeFittedProgram(temp.folder(), more.dump(), -1);
        EXPECT_FALSE(refusing.loadProgramFile(big));
        EXPECT_TRUE(refusing.programFileStatus().contains(juce::String(plugin::kMaxProgramFileBytes)))
            << refusing.programFileStatus();
    }
    plugin::RosinProcessor first;
    ASSERT_TRUE(first.loadProgramFile(file)) << first.programFileStatus();
    juce::MemoryBlock state;
    first.getStateInformation(state);
    EXPECT_LE(state.getSize(), static_cast<std::size_t>(plugin::kMaxStateBytes));
    std::printf("[ figures  ] file %lld bytes, state %zu bytes\n", static_cast<long long>(file.getSize()),
                state.getSize());
    plugin::RosinProcessor reopened;
    reopened.setStateInformation(state.getData(), static_cast<int>(state.getSize()));
    EXPECT_TRUE(reopened.programTitle().startsWith("my-cello")) << reopened.programTitle();
}

TEST(PluginProgramFile, ABrokenFileIsRefusedNamingFileAndFieldAndChangesNothing)
{
    TempFolder temp;
    plugin::RosinProcessor processor;
    const juce::String title = processor.programTitle();
    const std::vector<float> before = play(processor);

    const juce::File bad = writeFittedProgram(temp.folder(), R"([{"hz": 5, "db": 0}])");
    EXPECT_FALSE(processor.loadProgramFile(bad));
    const juce::String why = processor.programFileStatus();
    EXPECT_TRUE(why.contains(bad.getFullPathName())) << why;
    EXPECT_TRUE(why.contains("radiationGains")) << why;

    const juce::File missing = temp.folder().getChildFile("nowhere.json");
    EXPECT_FALSE(processor.loadProgramFile(missing));
    EXPECT_TRUE(processor.programFileStatus().contains("nowhere.json")) << processor.programFileStatus();

    const juce::File notJson = temp.folder().getChildFile("notes.json");
    notJson.replaceWithText("{\"format\": \"rosin-preset/1\", ");
    EXPECT_FALSE(processor.loadProgramFile(notJson));
    EXPECT_TRUE(processor.programFileStatus().contains("notes.json")) << processor.programFileStatus();

    EXPECT_EQ(processor.programTitle(), title);
    EXPECT_EQ(rmsDifference(play(processor), before), 0.0);
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::test
