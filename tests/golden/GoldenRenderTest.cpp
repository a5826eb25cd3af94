// Golden renders: a short render per friction law (`rosin render --gesture`, the bridge force) and
// per factory program (`rosin render --midi`, one note, what the plugin outputs), each compared with a
// reference stored in tests/golden/references. A physics or engine change that moves a render fails here, so
// it is made consciously: ROSIN_GOLDEN_UPDATE=1 writes new references (commit them with the reason).
//
// Every render runs the kernels' baseline path (ROSIN_SIMD=default), which every x86-64 machine has, so a
// reference is the same on any machine: the vector paths round single-precision sums differently, and a bow
// attack amplifies that (measured between the baseline and AVX2 paths: 1e-6 to 4e-5 for the steady bowings,
// but 0.24 over the whole render for the reconstructed program, whose attack is chaotic: 2e-2 already 50-75
// ms after the note-on). Tolerance: a relative rms difference of at most 1e-3, room for rounding-level
// changes in the steady bowings; for a chaotic attack any change of the arithmetic shows, and is a reason to
// update the references, said in the commit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <unistd.h>
#include <vector>

#include <juce_audio_formats/juce_audio_formats.h>

#include "cli/CliSupport.h"
#include "core/physics/modal/SimdLevel.h"

namespace rosin::test
{
namespace ROSIN_FILE_LOCAL
{

namespace fs = std::filesystem;
using cli::runRosin;

constexpr double kTolerance = 1e-3; // relative rms difference

std::vector<float> readWav(const fs::path& path)
{
    juce::WavAudioFormat wav;
    std::unique_ptr<juce::AudioFormatReader> reader(
        wav.createReaderFor(new juce::FileInputStream(juce::File(juce::String(path.string()))), true));
    if (reader == nullptr)
        return {};
    juce::AudioBuffer<float> buffer(1, static_cast<int>(reader->lengthInSamples));
    reader->read(&buffer, 0, buffer.getNumSamples(), 0, true, false);
    return {buffer.getReadPointer(0), buffer.getReadPointer(0) + buffer.getNumSamples()};
}

/// sqrt(sum (a - b)^2 / sum b^2)
double relativeRmsDifference(const std::vector<float>& a, const std::vector<float>& b)
{
    double difference = 0.0, reference = 0.0;
    for (std::size_t n = 0; n < b.size(); ++n)
    {
        difference += std::pow(double(a[n]) - double(b[n]), 2);
        reference += double(b[n]) * double(b[n]);
    }
    return std::sqrt(difference / reference);
}

/// One note, D3 at velocity 90 for 0.2 s, as a standard MIDI file.
fs::path writeNoteFile(const fs::path& folder)
{
    juce::MidiMessageSequence track;
    track.addEvent(juce::MidiMessage::noteOn(1, 50, static_cast<juce::uint8>(90)), 0.0);
    track.addEvent(juce::MidiMessage::noteOff(1, 50), 384.0); // ticks: 0.2 s at 120 bpm, 960 per quarter
    juce::MidiFile file;
    file.setTicksPerQuarterNote(960);
    file.addTrack(track);
    const fs::path path = folder / "note.mid";
    juce::FileOutputStream out(juce::File(juce::String(path.string())));
    EXPECT_TRUE(out.openedOk() && file.writeTo(out));
    return path;
}

class GoldenRender : public ::testing::Test
{
  protected:
    GoldenRender() { fs::create_directories(work); }
    ~GoldenRender() override { fs::remove_all(work); }

    /// Renders with `args` (plus --out) and compares with references/NAME.wav, or writes it when updating.
    void check(const std::string& name, std::vector<std::string> args)
    {
        const fs::path out = work / (name + ".wav");
        args.insert(args.end(), {"--out", out.string()});
        const auto result = runRosin(work.string(), args, "ROSIN_SIMD=default");
        ASSERT_EQ(result.status, 0) << name << ": " << result.err;
        const fs::path reference = fs::path(ROSIN_GOLDEN_DIR) / (name + ".wav");
        const char* update = std::getenv("ROSIN_GOLDEN_UPDATE");
        if (update != nullptr && std::string(update) == "1")
        {
            fs::copy_file(out, reference, fs::copy_options::overwrite_existing);
            std::cout << "[          ] wrote " << reference << "\n";
            return;
        }
        const auto rendered = readWav(out), stored = readWav(reference);
        ASSERT_FALSE(stored.empty()) << "no reference " << reference << " (ROSIN_GOLDEN_UPDATE=1 writes it)";
        ASSERT_EQ(rendered.size(), stored.size()) << name;
        const double difference = relativeRmsDifference(rendered, stored);
        std::cout << "[          ] " << name << ": relative rms difference " << difference << "\n";
        EXPECT_LE(difference, kTolerance)
            << name << " moved: if on purpose, ROSIN_GOLDEN_UPDATE=1 and commit";
    }

    fs::path work = fs::temp_directory_path() / ("rosin-golden-" + std::to_string(::getpid()));
};

TEST_F(GoldenRender, EveryFrictionLawBowsAsBefore)
{
    for (const char* law :
         {"classical", "reconstructed", "plastic", "viscous", "modified-bow", "modified-rod"})
        check(std::string("law-") + law,
              {"render", "--preset", "cello-plastic", "--friction", law, "--gesture",
               "steady:speed=0.1,force=1,beta=0.1,seconds=0.25", "--output", "force", "--scale", "1"});
}

TEST_F(GoldenRender, EveryFactoryProgramPlaysAsBefore)
{
    const fs::path note = writeNoteFile(work);
    for (const char* program :
         {"cello-classical", "cello-reconstructed", "cello-plastic", "cello-viscous", "cello-modified-bow",
          "cello-modified-rod", "violin-thermal", "galluzzo-rig", "schumacher-rig"})
        check(std::string("program-") + program,
              {"render", "--midi", note.string(), "--preset", program, "--tail", "0.05"});
}

// The kernels add their lanes in one tree whatever the vector width (physics/modal/VectorBlock.h), and the
// AVX2 and AVX-512 variants both fuse multiply-adds, so those two paths render the same bits: the plugin's
// engine with four strings and the radiating body (the demo phrase), and every friction law on one string.
// (The baseline path has no fused multiply-add and rounds differently.) Runs where the CPU has AVX-512.
TEST(KernelPaths, AvxTwoAndAvxFiveHundredTwelveRenderTheSameBits)
{
    if (physics::supportedSimdLevel() != physics::SimdLevel::V4)
        GTEST_SKIP() << "this CPU has no x86-64-v4 path to compare";
    const fs::path work = fs::temp_directory_path() / ("rosin-paths-" + std::to_string(::getpid()));
    fs::create_directories(work);
    std::vector<std::vector<std::string>> renders = {
        {"render", "--midi", std::string(ROSIN_DEMO_PHRASE), "--preset", "cello-plastic"}};
    for (const char* law :
         {"classical", "reconstructed", "plastic", "viscous", "modified-bow", "modified-rod"})
        renders.push_back({"render", "--preset", "cello-plastic", "--friction", law, "--gesture",
                           "steady:speed=0.1,force=1,beta=0.1,seconds=0.25", "--output", "force"});
    for (std::size_t k = 0; k < renders.size(); ++k)
    {
        std::vector<float> audio[2];
        const char* paths[2] = {"ROSIN_SIMD=x86-64-v3", "ROSIN_SIMD=x86-64-v4"};
        for (int p = 0; p < 2; ++p)
        {
            const fs::path out = work / ("r" + std::to_string(k) + "-" + std::to_string(p) + ".wav");
            auto args = renders[k];
            args.insert(args.end(), {"--out", out.string()});
            const auto result = runRosin(work.string(), args, paths[p]);
            ASSERT_EQ(result.status, 0) << result.err;
            audio[p] = readWav(out);
        }
        ASSERT_FALSE(audio[0].empty());
        EXPECT_TRUE(audio[0] == audio[1])
            << renders[k][1] << " " << renders[k][2] << " " << renders[k][4]
            << ": the two paths differ, relative rms " << relativeRmsDifference(audio[0], audio[1]);
    }
    fs::remove_all(work);
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::test
