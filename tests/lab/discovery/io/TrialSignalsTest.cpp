// Trial WAV files through JUCE: written and read back bit for bit, and every file that breaks the spec
// (PCM, wrong channel count or rate, truncated, missing, not a WAV) rejected with a message naming it.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <random>

#include <juce_audio_formats/juce_audio_formats.h>

#include "lab/discovery/DatasetFixtures.h"
#include "lab/discovery/DatasetReader.h"
#include "lab/discovery/io/TrialSignals.h"

namespace rosin::discovery
{
namespace ROSIN_FILE_LOCAL
{

namespace fs = std::filesystem;

// A WAV written by JUCE directly, so the tests can make the files the library refuses to write.
std::string slurpFile(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void writeRawWav(const fs::path& path, double sampleRate, const std::vector<std::vector<float>>& channels,
                 int bits)
{
    fs::create_directories(path.parent_path());
    const juce::File file(juce::String(fs::absolute(path).string()));
    file.deleteFile();
    auto stream = std::make_unique<juce::FileOutputStream>(file);
    ASSERT_TRUE(stream->openedOk());
    juce::WavAudioFormat wav;
    const int numChannels = static_cast<int>(channels.size());
    std::unique_ptr<juce::AudioFormatWriter> writer(wav.createWriterFor(
        stream.get(), sampleRate, juce::AudioChannelSet::discreteChannels(numChannels), bits, {}, 0));
    ASSERT_NE(writer, nullptr);
    stream.release();
    std::vector<const float*> pointers;
    for (const auto& c : channels)
        pointers.push_back(c.data());
    if (!channels.front().empty())
        ASSERT_TRUE(writer->writeFromFloatArrays(pointers.data(), numChannels,
                                                 static_cast<int>(channels.front().size())));
}

class TrialSignalsTest : public ::testing::Test
{
  protected:
    TrialSignalsTest()
    {
        folder.describe(std::string(test::kSpecExample));
        dataset = readDatasetDescription(folder.path());
    }
    const Trial& trial() const { return dataset.trials[0]; }
    fs::path wavPath() const { return fs::path(folder.path()) / trial().file; }

    // Two channels of `frames` float-representable values (bridge force, bow velocity).
    static std::vector<std::vector<double>> signals(std::size_t frames)
    {
        std::mt19937 rng(7);
        std::normal_distribution<float> noise(0.0f, 0.5f);
        std::vector<std::vector<double>> s(2, std::vector<double>(frames));
        for (std::size_t n = 0; n < frames; ++n)
        {
            s[0][n] = noise(rng);
            s[1][n] = 1.56f * static_cast<float>(n) / 44100.0f;
        }
        s[0][0] = std::numeric_limits<float>::denorm_min();
        s[0][1] = -std::numeric_limits<float>::max();
        s[0][2] = 1e-30f;
        return s;
    }

    // The DatasetError reading the trial gives (fails the test if none).
    DatasetError readError() const
    {
        try
        {
            readTrialSignals(dataset, trial());
        }
        catch (const DatasetError& e)
        {
            return e;
        }
        ADD_FAILURE() << "accepted";
        return DatasetError("", "", "");
    }

    test::DatasetFolder folder;
    Dataset dataset;
};

TEST_F(TrialSignalsTest, WriteThenReadIsBitExact)
{
    const auto written = signals(70000); // more than one read block
    writeTrialSignals(dataset, trial(), written);
    EXPECT_FALSE(fs::exists(wavPath().string() + ".part"));

    const TrialSignals back = readTrialSignals(dataset, trial());
    EXPECT_EQ(back.sampleRate, 44100);
    EXPECT_EQ(back.channels, dataset.channels);
    ASSERT_EQ(back.frames(), 70000u);
    for (std::size_t c = 0; c < 2; ++c)
        for (std::size_t n = 0; n < written[c].size(); ++n)
            ASSERT_EQ(back.samples[c][n], written[c][n]) << "channel " << c << " frame " << n;
    EXPECT_EQ(&back.channel("bowVelocity"), &back.samples[1]);
    EXPECT_THROW(back.channel("frictionForce"), std::out_of_range);
}

TEST_F(TrialSignalsTest, TheFileIsIeeeFloat32WithTheDatasetLayout)
{
    writeTrialSignals(dataset, trial(), signals(100));
    juce::WavAudioFormat wav;
    std::unique_ptr<juce::AudioFormatReader> reader(
        wav.createReaderFor(new juce::FileInputStream(juce::File(juce::String(wavPath().string()))), true));
    ASSERT_NE(reader, nullptr);
    EXPECT_TRUE(reader->usesFloatingPointData);
    EXPECT_EQ(reader->bitsPerSample, 32u);
    EXPECT_EQ(reader->numChannels, 2u);
    EXPECT_EQ(reader->sampleRate, 44100.0);
    EXPECT_EQ(reader->lengthInSamples, 100);
}

TEST_F(TrialSignalsTest, Pcm16IsRejected)
{
    writeRawWav(wavPath(), 44100, {{0.1f, 0.2f}, {0.0f, 0.0f}}, 16);
    const DatasetError e = readError();
    EXPECT_EQ(e.file(), wavPath().string());
    EXPECT_EQ(e.expected(), "IEEE float 32-bit samples (format rosin-measurements/1)");
    EXPECT_EQ(e.got(), "16-bit integer PCM samples");
    EXPECT_NE(std::string(e.what()).find(wavPath().string()), std::string::npos);
}

TEST_F(TrialSignalsTest, ChannelCountMismatchIsRejected)
{
    writeRawWav(wavPath(), 44100, {{0.1f}, {0.2f}, {0.3f}}, 32);
    const DatasetError e = readError();
    EXPECT_EQ(e.file(), wavPath().string());
    EXPECT_EQ(std::string(e.what()), wavPath().string() +
                                         ": expected 2 channels (bridgeForce, bowVelocity, as dataset.json "
                                         "lists them) but got 3 channels");
}

// Found by fuzzing: JUCE 7.0.5 casts channel indices past 128 to its channel enum (undefined behaviour), so
// a header claiming hundreds of channels is refused from the header's own fmt chunk before JUCE reads it.
TEST_F(TrialSignalsTest, HeaderClaimingHundredsOfChannelsIsRefusedBeforeJuceReadsIt)
{
    auto u16 = [](unsigned v) { return std::string{static_cast<char>(v & 0xff), static_cast<char>(v >> 8)}; };
    auto u32 = [&](unsigned v) { return u16(v & 0xffff) + u16(v >> 16); };
    auto fmt = [&](unsigned channels)
    {
        return "fmt " + u32(16) + u16(3) + u16(channels) + u32(44100) + u32(44100 * 4 * channels) +
               u16(4 * channels) + u16(32);
    };
    const std::string data = "data" + u32(8) + std::string(8, '\0');
    // Claimed in the only fmt chunk, and (as the fuzzer found next) in a second fmt chunk after the data,
    // which JUCE's reader also reads.
    for (const std::string& chunks : {fmt(300) + data, fmt(2) + data + fmt(253)})
    {
        const std::string body = "WAVE" + chunks;
        fs::create_directories(wavPath().parent_path());
        std::ofstream(wavPath(), std::ios::binary)
            << "RIFF" << u32(static_cast<unsigned>(body.size())) << body;
        const DatasetError e = readError();
        EXPECT_EQ(e.file(), wavPath().string());
        EXPECT_TRUE(e.got() == "300 channels" || e.got() == "253 channels") << e.what();
    }
}

// Found by fuzzing: JUCE's WAV reader allocates the size a metadata chunk claims before reading it, so a
// 756-byte file with a "cue " chunk claiming a gigabyte ran out of memory. Such a file is refused first.
TEST_F(TrialSignalsTest, ChunkClaimingMoreThanTheFileHoldsIsRefusedBeforeJuceReadsIt)
{
    writeTrialSignals(dataset, trial(), signals(10));
    std::string bytes = slurpFile(wavPath());
    const unsigned claimed = 0x40000000u;
    std::string cue = "cue ";
    for (int k = 0; k < 4; ++k)
        cue += static_cast<char>((claimed >> (8 * k)) & 0xff);
    bytes += cue + std::string(16, '\0');
    std::ofstream(wavPath(), std::ios::binary | std::ios::trunc) << bytes;
    const DatasetError e = readError();
    EXPECT_EQ(e.file(), wavPath().string());
    EXPECT_EQ(e.expected(), "a WAV file whose chunks fit inside it");
    EXPECT_NE(e.got().find("'cue ' of 1073741824 bytes"), std::string::npos) << e.what();
}

TEST_F(TrialSignalsTest, SampleRateMismatchIsRejected)
{
    writeRawWav(wavPath(), 48000, {{0.1f}, {0.2f}}, 32);
    const DatasetError e = readError();
    EXPECT_EQ(e.file(), wavPath().string());
    EXPECT_EQ(e.expected(), "a sample rate of 44100 Hz (dataset.json \"sampleRate\")");
    EXPECT_EQ(e.got(), "48000 Hz");
}

// Decision: a truncated file is rejected, never read in part: JUCE would pad it with zeros, which a scorer
// would take for a string that stopped sounding.
TEST_F(TrialSignalsTest, TruncatedFileIsRejectedNotZeroFilled)
{
    writeTrialSignals(dataset, trial(), signals(1000));
    const auto size = fs::file_size(wavPath());
    for (std::uintmax_t chop : {1u, 3u, 8u, 4000u})
    {
        SCOPED_TRACE(chop);
        writeTrialSignals(dataset, trial(), signals(1000));
        fs::resize_file(wavPath(), size - chop);
        const DatasetError e = readError();
        EXPECT_EQ(e.file(), wavPath().string());
        EXPECT_EQ(e.expected(), "1000 sample frames (8000 bytes, as the WAV header says)");
        EXPECT_NE(e.got().find("truncated"), std::string::npos) << e.what();
    }
}

TEST_F(TrialSignalsTest, FileCutInsideItsHeaderIsRejected)
{
    writeTrialSignals(dataset, trial(), signals(1000));
    for (std::uintmax_t keep : {0u, 4u, 11u, 12u, 20u, 40u, 43u})
    {
        SCOPED_TRACE(keep);
        writeTrialSignals(dataset, trial(), signals(1000));
        fs::resize_file(wavPath(), keep);
        const DatasetError e = readError();
        EXPECT_EQ(e.file(), wavPath().string()) << e.what();
        EXPECT_EQ(e.expected().rfind("a WAV file", 0), 0u) << e.what();
    }
}

TEST_F(TrialSignalsTest, MissingFileIsRejected)
{
    const DatasetError e = readError();
    EXPECT_EQ(e.file(), wavPath().string());
    EXPECT_EQ(e.expected(), "the WAV file of trial \"b0899-f03-a10\" (trials[0])");
    EXPECT_EQ(e.got(), "no such file");
}

TEST_F(TrialSignalsTest, NotAWavIsRejected)
{
    fs::create_directories(wavPath().parent_path());
    std::ofstream(wavPath()) << "bridgeForce,bowVelocity\n0.1,0.0\n";
    const DatasetError e = readError();
    EXPECT_EQ(e.file(), wavPath().string());
    EXPECT_EQ(e.expected(), "a WAV file (RIFF/WAVE with a data chunk)");
}

TEST_F(TrialSignalsTest, EmptyAndNonFiniteFilesAreRejected)
{
    writeRawWav(wavPath(), 44100, {{}, {}}, 32);
    EXPECT_EQ(readError().expected(), "at least one sample frame");

    writeRawWav(wavPath(), 44100, {{0.0f, std::numeric_limits<float>::quiet_NaN()}, {0.0f, 0.0f}}, 32);
    const DatasetError e = readError();
    EXPECT_EQ(e.expected(), "finite sample values");
    EXPECT_EQ(e.got(), "nan at frame 1 of channel bridgeForce");
}

TEST_F(TrialSignalsTest, WriterRefusesWhatTheReaderWouldReject)
{
    EXPECT_THROW(writeTrialSignals(dataset, trial(), {{0.1}}), DatasetError);             // 1 of 2 channels
    EXPECT_THROW(writeTrialSignals(dataset, trial(), {{0.1, 0.2}, {0.1}}), DatasetError); // unequal lengths
    EXPECT_THROW(writeTrialSignals(dataset, trial(), {{}, {}}), DatasetError);            // empty
    EXPECT_THROW(writeTrialSignals(dataset, trial(), {{1e300}, {0.0}}), DatasetError);    // inf as a float
    EXPECT_THROW(writeTrialSignals(dataset, trial(), {{std::nan("")}, {0.0}}), DatasetError);
    EXPECT_FALSE(fs::exists(wavPath()));
    EXPECT_FALSE(fs::exists(wavPath().string() + ".part"));
}

TEST_F(TrialSignalsTest, TrialFilesOutsideTheFolderAreRefused)
{
    Trial outside = trial();
    outside.file = "../escaped.wav";
    try
    {
        writeTrialSignals(dataset, outside, signals(10));
        FAIL() << "wrote outside the dataset folder";
    }
    catch (const DatasetError& e)
    {
        EXPECT_EQ(e.file(), dataset.descriptionPath());
        EXPECT_EQ(e.field(), "trials[0].file");
    }
    EXPECT_FALSE(fs::exists(fs::path(folder.path()).parent_path() / "escaped.wav"));
    EXPECT_THROW(readTrialSignals(dataset, outside), DatasetError);
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::discovery
