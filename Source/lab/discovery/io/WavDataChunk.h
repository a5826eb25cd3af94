#pragma once
// Where a WAV file's sample data starts, how long its header says it is and how much of it the file holds.
// JUCE's WAV reader trusts the header and fills a truncated file's missing samples with zeros; this lets
// readTrialSignals tell a truncated file from silence.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace rosin::discovery
{

struct WavDataChunk
{
    std::uint64_t offset = 0;        ///< of the first sample byte
    std::uint64_t declaredBytes = 0; ///< as the header says (RF64: the ds64 chunk's size if nonzero)
    std::uint64_t presentBytes = 0;  ///< what the file actually holds from `offset`, at most declaredBytes
    /// The channel count of every "fmt " chunk in the file (normally one), checked before JUCE reads the
    /// first: JUCE 7.0.5 casts channel indices past 128 to its channel enum (undefined behaviour, found by
    /// fuzzing), so a header claiming hundreds of channels never reaches it. A later fmt chunk never reaches
    /// JUCE (WavEssentialsStream.h); a mismatch there is still named, as the damage it is.
    std::vector<unsigned> formatChannels;
    /// A chunk other than the data that claims more bytes than the file holds ("'cue ' of 1073742462 bytes"),
    /// or empty: such a file is refused, named. (Found by fuzzing when JUCE read every chunk: its reader
    /// allocated the claimed size, 2 GB from a 756-byte file. JUCE now sees only the essential chunks.)
    std::string overlongChunk;
    bool rf64 = false;
    /// Where the first "fmt " chunk lies: header included, padding not (openWavEssentials gives JUCE only
    /// this chunk and the data).
    std::uint64_t formatChunkOffset = 0, formatChunkBytes = 0;
};

/// Walks the RIFF (or RF64) chunks to the "data" chunk. std::nullopt when the file is not RIFF/WAVE or has
/// no data chunk header.
std::optional<WavDataChunk> findWavDataChunk(const std::filesystem::path& file);

} // namespace rosin::discovery
