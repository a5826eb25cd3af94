// Runs the built `rosin` binary: help texts, error messages and exit statuses, and renders read back with
// JUCE.
#include <gtest/gtest.h>

#include "cli/CliSupport.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <sys/wait.h>

#include <juce_audio_formats/juce_audio_formats.h>

#include "cli/Dispatcher.h"
#include "core/config/TempFiles.h"
#include "core/physics/body/BridgeBody.h"
#include "core/physics/modal/SimdLevel.h"

namespace ROSIN_FILE_LOCAL
{

using rosin::test::cli::quote;
using rosin::test::cli::Result;
using rosin::test::cli::slurp;

class Cli : public ::testing::Test
{
  protected:
    // Runs rosin in the scratch folder with the source tree's presets (unless presetDir is given).
    Result rosin(const std::vector<std::string>& args, const std::string& presetDir = ROSIN_SOURCE_PRESET_DIR)
    {
        std::string command = "cd " + quote(dir.path()) + " && ROSIN_PRESET_DIR=" + quote(presetDir) + " " +
                              quote(ROSIN_BINARY);
        for (const auto& a : args)
        {
            command += ' ';
            command += quote(a);
        }
        const std::string out = dir.path() + "/stdout.txt", err = dir.path() + "/stderr.txt";
        command += " >";
        command += quote(out);
        command += " 2>";
        command += quote(err);
        const int raw = std::system(command.c_str());
        Result r;
        r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
        r.out = slurp(out);
        r.err = slurp(err);
        return r;
    }

    rosin::test::TempDir dir;
};

struct Wav
{
    int channels = 0;
    juce::int64 samples = 0;
    double sampleRate = 0.0;
    bool floatingPoint = false;
    unsigned bits = 0;
    juce::StringPairArray metadata;
    juce::AudioBuffer<float> data;
};

Wav readWav(const std::string& path)
{
    juce::WavAudioFormat format;
    std::unique_ptr<juce::AudioFormatReader> reader(
        format.createReaderFor(new juce::FileInputStream(juce::File(juce::String(path))), true));
    Wav w;
    if (reader == nullptr)
        return w;
    w.channels = static_cast<int>(reader->numChannels);
    w.samples = reader->lengthInSamples;
    w.sampleRate = reader->sampleRate;
    w.floatingPoint = reader->usesFloatingPointData;
    w.bits = reader->bitsPerSample;
    w.metadata = reader->metadataValues;
    w.data.setSize(w.channels, static_cast<int>(w.samples));
    reader->read(&w.data, 0, static_cast<int>(w.samples), 0, true, true);
    return w;
}

TEST_F(Cli, HelpDocumentsEveryCommandAndOption)
{
    const Result top = rosin({"--help"});
    EXPECT_EQ(top.status, 0);
    EXPECT_NE(top.out.find("render"), std::string::npos);

    const Result help = rosin({"render", "--help"});
    EXPECT_EQ(help.status, 0);
    for (const char* text : {"--gesture",
                             "--out",
                             "--output",
                             "radiated",
                             "--probe",
                             "--preset",
                             "--friction",
                             "--body",
                             "--sample-rate",
                             "--scale",
                             "steady:speed=0.05,force=1,beta=0.1,seconds=1",
                             "guettler:acceleration=1.56,force=1,beta=0.0899,seconds=0.5",
                             "rosin-gesture/1",
                             "bridgeForce",
                             "bowPointVelocity",
                             "frictionForce",
                             "bowVelocity",
                             "contactTemperature",
                             "classical",
                             "reconstructed",
                             "plastic",
                             "viscous",
                             "modified-bow",
                             "modified-rod",
                             "cello",
                             "violin",
                             "rigid",
                             "galluzzo-rig",
                             "8000..384000"})
        EXPECT_NE(help.out.find(text), std::string::npos) << text;
    EXPECT_EQ(rosin({"help", "render"}).out, help.out);
}

TEST_F(Cli, UsageErrorsExitWithTwo)
{
    EXPECT_EQ(rosin({}).status, 2);
    EXPECT_EQ(rosin({"frobnicate"}).status, 2);
    const Result r = rosin({"render", "--bogus"});
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("unknown option \"--bogus\""), std::string::npos) << r.err;
    EXPECT_EQ(rosin({"render", "--out"}).status, 2);
}

TEST_F(Cli, BadPresetFileNamesFileFieldAndExpectation)
{
    const std::string path = dir.write("foo.json", R"({"format":"rosin-preset/1","friction":"plasticc"})");
    const Result r = rosin({"render", "--preset", path, "--out", "x.wav"});
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("error: " + path +
                         ": field \"friction\": expected one of classical, reconstructed, "
                         "plastic, viscous, modified-bow, modified-rod but got \"plasticc\""),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(std::ifstream(dir.path() + "/x.wav").good()); // nothing written on bad input
}

TEST_F(Cli, BadPresetByNameInThePresetFolder)
{
    dir.write("broken.json", R"({"format":"rosin-preset/1","contact":{"radius":0.5}})");
    const Result r = rosin({"render", "--preset", "broken"}, dir.path());
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(
        r.err.find(dir.path() + "/broken.json: field \"contact.radius\": expected a number in 1e-06..0.01"),
        std::string::npos)
        << r.err;
    const Result missing = rosin({"render", "--preset", "nope"});
    EXPECT_EQ(missing.status, 1);
    EXPECT_NE(missing.err.find("galluzzo-rig"), std::string::npos) << missing.err; // lists what exists
}

TEST_F(Cli, BadGestureValuesAreRejected)
{
    Result r = rosin({"render", "--gesture", "steady:beta=0.9"});
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("field \"beta\": expected a number in 0.01..0.5 but got 0.9"), std::string::npos)
        << r.err;

    r = rosin({"render", "--gesture", "guettler:force=25"});
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("field \"force\""), std::string::npos) << r.err;

    const std::string script =
        dir.write("g.json", R"({"format":"rosin-gesture/1","segments":[{"seconds":1,"finger":0.05}]})");
    r = rosin({"render", "--gesture", script});
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find(script + ": field \"segments[0].finger\": expected a number in 0.1..1"),
              std::string::npos)
        << r.err;

    r = rosin({"render", "--gesture", "stedy"});
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("--gesture"), std::string::npos);

    for (const char* rate : {"1000", "500000", "44100.5", "fast"})
        EXPECT_EQ(rosin({"render", "--sample-rate", rate}).status, 1) << rate;
    EXPECT_EQ(rosin({"render", "--friction", "plasticc"}).status, 1);
    EXPECT_EQ(rosin({"render", "--body", "viola"}).status, 1);
}

TEST_F(Cli, UnwritableOutputIsAnErrorNamingTheFile)
{
    const Result r = rosin({"render", "--gesture", "steady:seconds=0.01", "--out", "/nonexistent-dir/x.wav"});
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("/nonexistent-dir/x.wav"), std::string::npos) << r.err;
}

TEST_F(Cli, RenderWritesAudioAndAFiveChannelProbe)
{
    const Result r = rosin({"render", "--gesture", "guettler:seconds=0.1", "--sample-rate", "44100", "--out",
                            "a.wav", "--output", "force", "--probe", "p.wav"});
    ASSERT_EQ(r.status, 0) << r.err;
    // The channel list is printed, names and units in file order.
    const auto at = [&](const char* s) { return r.out.find(s); };
    EXPECT_LT(at("1 bridgeForce [N]"), at("2 bowPointVelocity [m/s]"));
    EXPECT_LT(at("2 bowPointVelocity [m/s]"), at("3 frictionForce [N]"));
    EXPECT_LT(at("3 frictionForce [N]"), at("4 bowVelocity [m/s]"));
    EXPECT_LT(at("4 bowVelocity [m/s]"), at("5 contactTemperature [K]"));
    EXPECT_NE(at("5 contactTemperature [K]"), std::string::npos);

    const Wav audio = readWav(dir.path() + "/a.wav");
    EXPECT_EQ(audio.channels, 1);
    EXPECT_EQ(audio.samples, 4410);
    EXPECT_EQ(audio.sampleRate, 44100.0);
    EXPECT_TRUE(audio.floatingPoint);
    EXPECT_EQ(audio.bits, 32u);
    EXPECT_NEAR(audio.data.getMagnitude(0, 0, 4410), 0.8913, 1e-3); // peak normalised to -1 dBFS

    const Wav probe = readWav(dir.path() + "/p.wav");
    ASSERT_EQ(probe.channels, 5);
    EXPECT_EQ(probe.samples, 4410);
    EXPECT_TRUE(probe.floatingPoint);
    EXPECT_EQ(probe.bits, 32u);
    EXPECT_NE(probe.metadata.getValue("ICMT", "").indexOf("contactTemperature[K]"), -1);
    for (int k = 0; k < 4410; ++k)
    {
        // bowVelocity in m/s, physical: exactly a k / fs (to float precision) from rest.
        ASSERT_FLOAT_EQ(probe.data.getSample(3, k), static_cast<float>(1.56 * (k / 44100.0))) << k;
        for (int c = 0; c < 5; ++c)
            ASSERT_TRUE(std::isfinite(probe.data.getSample(c, k)));
    }
    // The listening file is the probe's bridge force times one constant, taken at the probe's peak.
    int peak = 0;
    for (int i = 1; i < 4410; ++i)
        if (std::abs(probe.data.getSample(0, i)) > std::abs(probe.data.getSample(0, peak)))
            peak = i;
    ASSERT_GT(std::abs(probe.data.getSample(0, peak)), 0.0f);
    const double scale = audio.data.getSample(0, peak) / static_cast<double>(probe.data.getSample(0, peak));
    const auto printed = r.out.find("bridge force x ");
    ASSERT_NE(printed, std::string::npos);
    EXPECT_NEAR(std::stod(r.out.substr(printed + 15)), scale,
                1e-5 * scale); // the printed scale is the one used
    for (int i = 0; i < 4410; ++i)
        ASSERT_NEAR(audio.data.getSample(0, i), scale * probe.data.getSample(0, i), 1e-5) << i;
    EXPECT_GT(probe.data.getMagnitude(4, 0, 4410), 0.0f); // plastic friction heats the contact
}

// By default --out is what a listener hears: the probe's bridge force through the preset's body
// (BodyRadiation.h), one scale for the whole file; a second body, fed the probe's force, gives the same.
TEST_F(Cli, RenderWritesTheRadiatedSoundByDefault)
{
    const Result r =
        rosin({"render", "--gesture", "guettler:seconds=0.1", "--out", "a.wav", "--probe", "p.wav"});
    ASSERT_EQ(r.status, 0) << r.err;
    const auto printed = r.out.find("sound pressure at 1 m radiated by the cello body x ");
    ASSERT_NE(printed, std::string::npos) << r.out;
    const Wav audio = readWav(dir.path() + "/a.wav");
    const Wav probe = readWav(dir.path() + "/p.wav");
    rosin::physics::BridgeBody body;
    body.configure(rosin::physics::celloBody(), 48000.0, 2.0 * 3.141592653589793 * 0.45 * 48000.0);
    std::vector<double> pressure;
    double peak = 0.0;
    for (int i = 0; i < probe.samples; ++i)
    {
        body.advance(probe.data.getSample(0, i));
        pressure.push_back(body.radiatedPressure());
        peak = std::max(peak, std::abs(pressure.back()));
    }
    ASSERT_GT(peak, 0.0);
    const double scale = 0.8912509381337456 / peak;
    for (int i = 0; i < probe.samples; ++i)
        ASSERT_NEAR(audio.data.getSample(0, i), scale * pressure[static_cast<std::size_t>(i)], 1e-4) << i;
    EXPECT_NE(
        rosin({"render", "--gesture", "steady:seconds=0.01", "--output", "loudness"}).err.find("--output"),
        std::string::npos);
}

TEST_F(Cli, RendersAGestureScript)
{
    dir.write("g.json", R"({"format":"rosin-gesture/1","segments":[
        {"seconds":0.02,"force":{"from":0.5,"to":1.0},"speed":0.1,"beta":0.1},
        {"seconds":0.03,"acceleration":-1.0,"finger":{"to":0.8}}]})");
    const Result r = rosin({"render", "--gesture", "g.json", "--preset", "cello-classical", "--body", "rigid",
                            "--sample-rate", "48000", "--out", "a.wav", "--probe", "p.wav"});
    ASSERT_EQ(r.status, 0) << r.err;
    const Wav probe = readWav(dir.path() + "/p.wav");
    EXPECT_EQ(probe.channels, 5);
    EXPECT_EQ(probe.samples, 2400);
    EXPECT_FLOAT_EQ(probe.data.getSample(3, 0), 0.1f);
    EXPECT_FLOAT_EQ(probe.data.getSample(3, 960 + 100), static_cast<float>(0.1 - 1.0 * (100 / 48000.0)));
    EXPECT_EQ(probe.data.getMagnitude(4, 0, 2400), 0.0f); // the classical curve has no temperature
}

TEST_F(Cli, EveryShippedPresetRendersFiniteOutput)
{
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(ROSIN_SOURCE_PRESET_DIR))
        if (entry.path().extension() == ".json")
            names.push_back(entry.path().stem().string());
    ASSERT_FALSE(names.empty());
    for (const auto& name : names)
    {
        SCOPED_TRACE(name);
        const Result r = rosin({"render", "--preset", name, "--gesture", "steady:seconds=0.05,speed=0.1",
                                "--out", "a.wav", "--probe", "p.wav"});
        ASSERT_EQ(r.status, 0) << r.err;
        EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
        const Wav probe = readWav(dir.path() + "/p.wav");
        ASSERT_GE(probe.channels, 5); // a rig preset (cantilever) adds displacement and acceleration
        ASSERT_EQ(probe.samples, 2400);
        for (int c = 0; c < 5; ++c)
            for (int k = 0; k < 2400; ++k)
                ASSERT_TRUE(std::isfinite(probe.data.getSample(c, k))) << c << " " << k;
        EXPECT_GT(probe.data.getMagnitude(0, 0, 2400), 0.0f); // the string moved
    }
}

TEST(CliInProcess, DispatcherIsCallableFromALibrary)
{
    std::ostringstream out, err;
    EXPECT_EQ(rosin::cli::run({"--version"}, out, err), 0);
    EXPECT_EQ(out.str().rfind("rosin ", 0), 0u);
    EXPECT_NE(
        out.str().find(std::string("kernels: ") + rosin::physics::simdLevelName(rosin::physics::simdLevel())),
        std::string::npos)
        << out.str();
    std::ostringstream out2, err2;
    EXPECT_EQ(rosin::cli::run({"render", "--gesture", "guettler:beta=0.6"}, out2, err2), 1);
    EXPECT_NE(err2.str().find("field \"beta\""), std::string::npos) << err2.str();
    std::ostringstream out3, err3;
    EXPECT_EQ(rosin::cli::run({"render", "--out", "same.wav", "--probe", "./same.wav"}, out3, err3), 1);
    EXPECT_NE(err3.str().find("a different file from --out"), std::string::npos) << err3.str();
}

} // namespace ROSIN_FILE_LOCAL
