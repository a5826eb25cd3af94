#include "lab/discovery/io/TrialSignals.h"

#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <stdexcept>

#include <juce_audio_formats/juce_audio_formats.h>

#include "core/gesture/GestureLimits.h"
#include "lab/discovery/TrialPath.h"
#include "lab/discovery/io/WavDataChunk.h"
#include "lab/discovery/io/WavEssentialsStream.h"

namespace rosin::discovery
{

namespace fs = std::filesystem;

namespace
{
// Frames per read, so a long trial needs no second full-length float copy.
constexpr int kBlockFrames = 1 << 16;

std::string trialRef(const Dataset& dataset, const Trial& trial)
{
    const auto index = dataset.trialIndex(trial.id);
    return "trial \"" + trial.id + "\"" + (index ? " (trials[" + std::to_string(*index) + "])" : "");
}

std::string channelList(const std::vector<Channel>& channels)
{
    std::string text;
    for (const auto& c : channels)
        text += (text.empty() ? "" : ", ") + c.name;
    return text;
}

std::string describeSampleFormat(const juce::AudioFormatReader& reader)
{
    if (reader.usesFloatingPointData)
        return "IEEE float " + std::to_string(reader.bitsPerSample) + "-bit samples";
    return std::to_string(reader.bitsPerSample) + "-bit integer PCM samples";
}

juce::File juceFile(const fs::path& path)
{
    return juce::File(juce::String(fs::absolute(path).string()));
}

std::unique_ptr<juce::AudioFormatReader> openWav(const std::string& name, const fs::path& path,
                                                 const WavDataChunk& chunk)
{
    auto stream = openWavEssentials(juceFile(path), chunk); // no metadata chunk reaches JUCE
    if (stream == nullptr)
        throw DatasetError(name, "", "a readable file", "a file that cannot be opened");
    juce::WavAudioFormat wav;
    std::unique_ptr<juce::AudioFormatReader> reader(wav.createReaderFor(stream.release(), true));
    if (reader == nullptr)
        throw DatasetError(name, "", "a WAV file JUCE can read", "a damaged or unsupported WAV header");
    return reader;
}

void checkChannelCount(const std::string& name, std::size_t channels, const Dataset& dataset)
{
    if (channels != dataset.channels.size())
        throw DatasetError(name, "",
                           std::to_string(dataset.channels.size()) + " channels (" +
                               channelList(dataset.channels) + ", as dataset.json lists them)",
                           std::to_string(channels) + " channels");
}

void checkLayout(const std::string& name, const juce::AudioFormatReader& reader, const Dataset& dataset)
{
    if (!reader.usesFloatingPointData || reader.bitsPerSample != 32)
        throw DatasetError(name, "", "IEEE float 32-bit samples (format rosin-measurements/1)",
                           describeSampleFormat(reader));
    checkChannelCount(name, reader.numChannels, dataset);
    if (reader.sampleRate != dataset.sampleRate)
        throw DatasetError(name, "",
                           "a sample rate of " + std::to_string(dataset.sampleRate) +
                               " Hz (dataset.json \"sampleRate\")",
                           physics::formatNumber(reader.sampleRate) + " Hz");
}

// JUCE zero-fills what a truncated file lacks; the RIFF chunk sizes show it.
void checkComplete(const std::string& name, const WavDataChunk& chunk, const juce::AudioFormatReader& reader)
{
    const std::uint64_t frameBytes = reader.numChannels * 4u;
    const auto frames = static_cast<std::uint64_t>(reader.lengthInSamples);
    if (frames == 0)
        throw DatasetError(name, "", "at least one sample frame", "an empty data chunk");
    if (frames * frameBytes > chunk.presentBytes)
        throw DatasetError(name, "",
                           std::to_string(frames) + " sample frames (" + std::to_string(frames * frameBytes) +
                               " bytes, as the WAV header says)",
                           "only " + std::to_string(chunk.presentBytes) +
                               " bytes of sample data: the file is truncated");
    if (frames > static_cast<std::uint64_t>(std::numeric_limits<int>::max()))
        throw DatasetError(name, "", "at most 2^31 - 1 sample frames", std::to_string(frames));
}
} // namespace

const std::vector<double>& TrialSignals::channel(const std::string& name) const
{
    for (std::size_t c = 0; c < channels.size(); ++c)
        if (channels[c].name == name)
            return samples.at(c);
    throw std::out_of_range("no channel \"" + name + "\" in the trial signals (" + channelList(channels) +
                            ")");
}

TrialSignals readTrialSignals(const Dataset& dataset, const Trial& trial)
{
    const fs::path path = trialFilePath(dataset, trial);
    const std::string name = path.string();
    std::error_code ec;
    if (!fs::is_regular_file(path, ec))
        throw DatasetError(name, "", "the WAV file of " + trialRef(dataset, trial),
                           fs::exists(path, ec) ? "something that is not a regular file" : "no such file");

    const auto chunk = findWavDataChunk(path);
    if (!chunk)
        throw DatasetError(name, "", "a WAV file (RIFF/WAVE with a data chunk)",
                           "a file without one (another format, or cut short in its header)");
    if (!chunk->overlongChunk.empty()) // before JUCE reads the header (WavDataChunk.h)
        throw DatasetError(name, "", "a WAV file whose chunks fit inside it",
                           "a chunk " + chunk->overlongChunk + " in a file of " +
                               std::to_string(std::filesystem::file_size(path)) + " bytes");
    for (const unsigned channels : chunk->formatChannels) // before JUCE reads the header (WavDataChunk.h)
        checkChannelCount(name, channels, dataset);
    const auto reader = openWav(name, path, *chunk);
    checkLayout(name, *reader, dataset);
    checkComplete(name, *chunk, *reader);

    TrialSignals signals;
    signals.sampleRate = dataset.sampleRate;
    signals.channels = dataset.channels;
    const int numChannels = static_cast<int>(dataset.channels.size());
    const auto frames = static_cast<std::size_t>(reader->lengthInSamples);
    signals.samples.assign(dataset.channels.size(), std::vector<double>(frames));

    juce::AudioBuffer<float> block(numChannels, kBlockFrames);
    for (std::size_t start = 0; start < frames; start += kBlockFrames)
    {
        const int count = static_cast<int>(std::min<std::size_t>(kBlockFrames, frames - start));
        if (!reader->read(block.getArrayOfWritePointers(), numChannels, static_cast<juce::int64>(start),
                          count))
            throw DatasetError(name, "", "readable sample data",
                               "a read error at frame " + std::to_string(start));
        for (int c = 0; c < numChannels; ++c)
        {
            const float* in = block.getReadPointer(c);
            auto& out = signals.samples[static_cast<std::size_t>(c)];
            for (int n = 0; n < count; ++n)
            {
                if (!std::isfinite(in[n]))
                    throw DatasetError(name, "", "finite sample values",
                                       physics::formatNumber(in[n]) + " at frame " +
                                           std::to_string(start + n) + " of channel " +
                                           dataset.channels[static_cast<std::size_t>(c)].name);
                out[start + static_cast<std::size_t>(n)] = in[n];
            }
        }
    }
    return signals;
}

namespace
{
// Rounded to float as the file stores them; every value must be finite there too.
std::vector<std::vector<float>> toFloat(const std::string& name, const Dataset& dataset,
                                        const std::vector<std::vector<double>>& channels)
{
    if (channels.empty() || channels.size() != dataset.channels.size())
        throw DatasetError(name, "",
                           std::to_string(dataset.channels.size()) + " channels (" +
                               channelList(dataset.channels) + ", as the dataset lists them)",
                           std::to_string(channels.size()) + " channels");
    std::vector<std::vector<float>> out(channels.size());
    for (std::size_t c = 0; c < channels.size(); ++c)
    {
        if (channels[c].empty() || channels[c].size() != channels.front().size())
            throw DatasetError(name, "", "channels of one non-zero length",
                               std::to_string(channels[c].size()) + " samples in channel " +
                                   dataset.channels[c].name + ", " + std::to_string(channels.front().size()) +
                                   " in " + dataset.channels.front().name);
        out[c].resize(channels[c].size());
        for (std::size_t n = 0; n < channels[c].size(); ++n)
        {
            out[c][n] = static_cast<float>(channels[c][n]);
            if (!std::isfinite(out[c][n]))
                throw DatasetError(name, "", "values finite as 32-bit floats",
                                   physics::formatNumber(channels[c][n]) + " at frame " + std::to_string(n) +
                                       " of channel " + dataset.channels[c].name);
        }
    }
    if (out.front().size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
        throw DatasetError(name, "", "at most 2^31 - 1 sample frames", std::to_string(out.front().size()));
    return out;
}

void writeWav(const std::string& name, const fs::path& path, int sampleRate,
              const std::vector<std::vector<float>>& channels)
{
    const juce::File file = juceFile(path);
    file.deleteFile();
    auto stream = std::make_unique<juce::FileOutputStream>(file);
    if (!stream->openedOk())
        throw DatasetError(name, "", "a writable file", stream->getStatus().getErrorMessage().toStdString());
    juce::WavAudioFormat wav;
    const int numChannels = static_cast<int>(channels.size());
    // 32 bits selects IEEE float in JUCE's WAV writer; a discrete layout carries no speaker assignment.
    std::unique_ptr<juce::AudioFormatWriter> writer(wav.createWriterFor(
        stream.get(), sampleRate, juce::AudioChannelSet::discreteChannels(numChannels), 32, {}, 0));
    if (writer == nullptr)
        throw DatasetError(name, "", "a WAV writer for " + std::to_string(numChannels) + " channels", "none");
    stream.release(); // owned by the writer now

    std::vector<const float*> pointers;
    for (const auto& c : channels)
        pointers.push_back(c.data());
    const bool written =
        writer->writeFromFloatArrays(pointers.data(), numChannels, static_cast<int>(channels.front().size()));
    const bool flushed = written && writer->flush();
    writer.reset(); // rewrites the header with the final length
    if (!flushed)
        throw DatasetError(name, "", "a complete WAV file", "a write error (disk full?)");
}
} // namespace

void writeTrialSignals(const Dataset& dataset, const Trial& trial,
                       const std::vector<std::vector<double>>& channels)
{
    const fs::path path = trialFilePath(dataset, trial);
    const std::string name = path.string();
    const auto values = toFloat(name, dataset, channels);

    std::error_code ec;
    fs::create_directories(path.parent_path(), ec);
    if (ec)
        throw DatasetError(path.parent_path().string(), "", "a folder that can be created", ec.message());
    fs::path partial = path;
    partial += ".part";
    try
    {
        writeWav(name, partial, dataset.sampleRate, values);
    }
    catch (...)
    {
        fs::remove(partial, ec);
        throw;
    }
    fs::rename(partial, path, ec);
    if (ec)
        throw DatasetError(name, "", "a file that can be replaced", ec.message());
}

} // namespace rosin::discovery
