#include "lab/discovery/io/WavDataChunk.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>
#include <fstream>

namespace rosin::discovery
{

namespace
{
std::uint64_t littleEndian(const unsigned char* bytes, int count)
{
    std::uint64_t value = 0;
    for (int i = count - 1; i >= 0; --i)
        value = (value << 8) | bytes[i];
    return value;
}
} // namespace

std::optional<WavDataChunk> findWavDataChunk(const std::filesystem::path& file)
{
    std::error_code ec;
    const std::uint64_t size = std::filesystem::file_size(file, ec);
    std::ifstream in(file, std::ios::binary);
    if (ec || !in)
        return std::nullopt;
    std::array<unsigned char, 12> riff{};
    if (!in.read(reinterpret_cast<char*>(riff.data()), riff.size()))
        return std::nullopt;
    const bool rf64 = std::memcmp(riff.data(), "RF64", 4) == 0;
    if ((!rf64 && std::memcmp(riff.data(), "RIFF", 4) != 0) || std::memcmp(riff.data() + 8, "WAVE", 4) != 0)
        return std::nullopt;

    std::uint64_t position = 12, rf64DataBytes = 0;
    std::array<unsigned char, 16> header{};
    std::vector<unsigned> formatChannels;
    std::optional<WavDataChunk> data;
    std::string overlong;
    std::uint64_t formatOffset = 0, formatBytes = 0;
    // Every chunk, also after the data, so that a damaged one is named (JUCE sees only the essential ones).
    while (position + 8 <= size)
    {
        in.seekg(static_cast<std::streamoff>(position));
        if (!in.read(reinterpret_cast<char*>(header.data()), 8))
            break;
        const std::uint64_t length = littleEndian(header.data() + 4, 4);
        const std::uint64_t body = position + 8;
        if (!data && std::memcmp(header.data(), "data", 4) == 0)
        {
            data.emplace();
            data->offset = body;
            // In RF64 a nonzero ds64 data size wins over the chunk's own, as in JUCE's reader (which is
            // handed the sizes decided here, rewritten: WavEssentialsStream.h).
            data->declaredBytes = rf64 && rf64DataBytes > 0 ? rf64DataBytes : length;
            data->presentBytes = std::min(data->declaredBytes, size - body);
        }
        const bool isData = std::memcmp(header.data(), "data", 4) == 0;
        if (!isData && body + length > size && overlong.empty())
        {
            char text[64];
            std::snprintf(text, sizeof text, "'%.4s' of %llu bytes",
                          reinterpret_cast<const char*>(header.data()),
                          static_cast<unsigned long long>(length));
            overlong = text;
        }
        const bool isFormat = std::memcmp(header.data(), "fmt ", 4) == 0;
        const bool isDs64 = rf64 && std::memcmp(header.data(), "ds64", 4) == 0;
        if (isFormat && formatBytes == 0 && body + length <= size)
            formatOffset = position, formatBytes = 8 + length;
        // fmt: format tag (2 bytes), then the channel count (2 bytes).
        if (isFormat && length >= 4 && in.read(reinterpret_cast<char*>(header.data()), 4))
            formatChannels.push_back(static_cast<unsigned>(littleEndian(header.data() + 2, 2)));
        // ds64: riffSize (8 bytes), then dataSize (8 bytes), which replaces the data chunk's 32-bit size.
        if (isDs64 && length >= 16 && in.read(reinterpret_cast<char*>(header.data()), 16))
            rf64DataBytes = littleEndian(header.data() + 8, 8);
        position = body + length + (length & 1); // chunks are padded to even sizes
    }
    if (data)
    {
        data->formatChannels = std::move(formatChannels);
        data->overlongChunk = overlong;
        data->rf64 = rf64;
        data->formatChunkOffset = formatOffset, data->formatChunkBytes = formatBytes;
    }
    return data;
}

} // namespace rosin::discovery
