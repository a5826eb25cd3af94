// Trial files carry metadata chunks JUCE should never parse (fuzzing found its XML parser reading past a
// damaged iXML chunk): what reaches JUCE is exactly the header, the format and the data, and the samples
// still come back bit for bit, from RIFF and from RF64 files, with the metadata before or after the data.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "lab/discovery/io/TrialSignals.h"
#include "lab/discovery/io/WavEssentialsStream.h"

namespace rosin::discovery
{
namespace ROSIN_FILE_LOCAL
{

namespace fs = std::filesystem;

std::string u16(unsigned v)
{
    return {static_cast<char>(v & 0xff), static_cast<char>((v >> 8) & 0xff)};
}
std::string u32(unsigned v)
{
    return u16(v & 0xffff) + u16(v >> 16);
}
std::string u64(unsigned long long v)
{
    return u32(static_cast<unsigned>(v)) + u32(static_cast<unsigned>(v >> 32));
}

std::string chunk(const std::string& id, const std::string& body)
{
    return id + u32(static_cast<unsigned>(body.size())) + body +
           (body.size() % 2 ? std::string(1, '\0') : "");
}

const std::string kFormat = chunk("fmt ", u16(3) + u16(2) + u32(44100) + u32(44100 * 8) + u16(8) + u16(32));
const std::vector<float> kFrames = {0.25f, -1.5f, 1e-30f, 3.0f, -0.125f, 7.5f}; // 3 frames, 2 channels

std::string sampleBytes()
{
    std::string bytes(kFrames.size() * 4, '\0');
    std::memcpy(bytes.data(), kFrames.data(), bytes.size()); // little-endian, as the test machines are
    return bytes;
}

std::string riff(const std::string& chunks)
{
    return "RIFF" + u32(static_cast<unsigned>(4 + chunks.size())) + "WAVE" + chunks;
}

// The header JUCE is handed for an RF64 file: sizes rewritten from what the chunk walker decided.
std::string rf64Head(const std::string& format, std::size_t dataBytes)
{
    const std::size_t riffBytes = 4 + 36 + format.size() + 8 + dataBytes;
    return "RF64" + u32(0xffffffffu) + "WAVE" + "ds64" + u32(28) + u64(riffBytes) + u64(dataBytes) + u64(0) +
           u32(0) + format + "data" + u32(0xffffffffu);
}

// What a damaged file's iXML chunk looked like: an XML element cut off with no closing bracket.
const std::string kDamagedIxml = chunk("iXML", "<q>\x13\x8e\xff\xff\xffNSt6lo\xdf\xff\xff");
const std::string kList = chunk("LIST", "INFOISFT" + u32(5) + "rosin" + std::string(1, '\0'));

class WavEssentialsStreamTest : public ::testing::Test
{
  protected:
    WavEssentialsStreamTest()
    {
        dataset.folder = folder.string();
        dataset.sampleRate = 44100;
        dataset.channels = {{"bridgeForce", "N"}, {"bowVelocity", "m/s"}};
        trial.id = "t";
        trial.file = "t.wav";
        fs::create_directories(folder);
    }
    ~WavEssentialsStreamTest() override { fs::remove_all(folder); }

    void write(const std::string& bytes) const { std::ofstream(path(), std::ios::binary) << bytes; }
    fs::path path() const { return folder / trial.file; }

    std::string essentials() const
    {
        const auto found = findWavDataChunk(path());
        EXPECT_TRUE(found.has_value());
        auto stream = openWavEssentials(juce::File(juce::String(path().string())), *found);
        EXPECT_NE(stream, nullptr);
        juce::MemoryBlock block;
        stream->readIntoMemoryBlock(block);
        return std::string(static_cast<const char*>(block.getData()), block.getSize());
    }

    void expectSamplesBack() const
    {
        const TrialSignals back = readTrialSignals(dataset, trial);
        ASSERT_EQ(back.frames(), 3u);
        for (std::size_t n = 0; n < 3; ++n)
            for (std::size_t c = 0; c < 2; ++c)
                EXPECT_EQ(back.samples[c][n], kFrames[2 * n + c]) << "frame " << n << " channel " << c;
    }

    fs::path folder = fs::temp_directory_path() / ("rosin-wav-essentials-" + std::to_string(::getpid()));
    Dataset dataset;
    Trial trial;
};

TEST_F(WavEssentialsStreamTest, MetadataChunksNeverReachTheReader)
{
    const std::string data = chunk("data", sampleBytes());
    write(riff(kList + kDamagedIxml + kFormat + chunk("bext", std::string(7, 'b')) + data + kDamagedIxml));
    EXPECT_EQ(essentials(), riff(kFormat + data));
    expectSamplesBack();
}

TEST_F(WavEssentialsStreamTest, TheFirstFormatChunkIsTheOneKept)
{
    const std::string data = chunk("data", sampleBytes());
    write(riff(kFormat + data + kFormat));
    EXPECT_EQ(essentials(), riff(kFormat + data));
}

// RF64 keeps the data size in its ds64 chunk; the data chunk's own size reads 0xffffffff.
TEST_F(WavEssentialsStreamTest, Rf64SizesAreWrittenAnewFromTheDs64Chunk)
{
    const std::string samples = sampleBytes();
    const std::string rest = kDamagedIxml + kFormat + "data" + u32(0xffffffffu) + samples;
    const std::size_t riffBytes = 4 + 8 + 28 + rest.size(); // "WAVE", the ds64 chunk, the rest
    const std::string ds64 = chunk("ds64", u64(riffBytes) + u64(samples.size()) + u64(3) + u32(0));
    write("RF64" + u32(0xffffffffu) + "WAVE" + ds64 + rest);
    EXPECT_EQ(essentials(), rf64Head(kFormat, samples.size()) + samples);
    expectSamplesBack();
}

// Found by fuzzing: an RF64 file whose ds64 data size is smaller than its data chunk's own size. JUCE's
// reader took the ds64 size and read the rest of the samples as further chunks (one claimed 2 GB); the data
// handed to it now ends where the ds64 size says.
TEST_F(WavEssentialsStreamTest, Rf64DataEndsWhereDs64Says)
{
    const std::string samples = sampleBytes();
    const std::string trailing = "smpl" + u32(0x80000000u) + std::string(32, '\x8b');
    const std::string rest = kFormat + "data" + u32(0x2a00) + samples + trailing;
    const std::size_t riffBytes = 4 + 8 + 28 + rest.size();
    const std::string ds64 = chunk("ds64", u64(riffBytes) + u64(samples.size()) + u64(3) + u32(0));
    write("RF64" + u32(0xffffffffu) + "WAVE" + ds64 + rest);
    EXPECT_EQ(essentials(), rf64Head(kFormat, samples.size()) + samples);
    expectSamplesBack();
}

// Found by fuzzing: a ds64 data size above 2^63, which JUCE reads as negative and so ignores, taking the data
// chunk's own size instead and reading what follows (an iXML chunk) as metadata. The stream says what the
// walker decided, and the file is refused as truncated.
TEST_F(WavEssentialsStreamTest, Rf64DataSizeJuceReadsAsNegativeIsTruncation)
{
    const std::string samples = sampleBytes();
    const unsigned long long huge = 0xbaa9be58fffffc50ull;
    const std::string rest =
        kFormat + "data" + u32(static_cast<unsigned>(samples.size())) + samples + kDamagedIxml;
    const std::string ds64 = chunk("ds64", u64(1000) + u64(huge) + u64(0) + u32(0));
    write("RF64" + u32(0xffffffffu) + "WAVE" + ds64 + rest);
    EXPECT_EQ(essentials(), rf64Head(kFormat, huge) + samples + kDamagedIxml);
    try
    {
        readTrialSignals(dataset, trial);
        ADD_FAILURE() << "accepted";
    }
    catch (const DatasetError& e)
    {
        EXPECT_NE(std::string(e.what()).find("truncated"), std::string::npos) << e.what();
    }
}

// Found by fuzzing: a ds64 chunk of odd length lost its pad byte on the way, and JUCE read the next chunk one
// byte off. Odd-length chunks are walked over with their pad; the fmt chunk keeps it.
TEST_F(WavEssentialsStreamTest, OddLengthChunksKeepTheirPadByte)
{
    const std::string samples = sampleBytes();
    const std::string oddFormat =
        chunk("fmt ", u16(3) + u16(2) + u32(44100) + u32(44100 * 8) + u16(8) + u16(32) + std::string(1, 'x'));
    const std::string rest = oddFormat + "data" + u32(0xffffffffu) + samples;
    const std::size_t riffBytes = 4 + 8 + 30 + rest.size();
    const std::string ds64 = chunk("ds64", u64(riffBytes) + u64(samples.size()) + u64(3) + u32(0) + "y");
    ASSERT_EQ(ds64.size(), 8u + 30u); // 29 bytes and the pad
    write("RF64" + u32(0xffffffffu) + "WAVE" + ds64 + rest);
    EXPECT_EQ(essentials(), rf64Head(oddFormat, samples.size()) + samples);
    expectSamplesBack();
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::discovery
