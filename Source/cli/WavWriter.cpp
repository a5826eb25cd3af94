#include "cli/WavWriter.h"

#include <stdexcept>

#include <juce_audio_formats/juce_audio_formats.h>

namespace rosin::cli
{

// The samples go to a temporary file beside the target, which replaces the target only when close() has
// finished the header: a render that fails or is killed leaves the old file (or none), never a torn one.
struct WavWriter::Impl
{
    std::unique_ptr<juce::TemporaryFile> temporary;
    std::unique_ptr<juce::AudioFormatWriter> writer;
};

WavWriter::WavWriter(const std::string& path, double sampleRate, int numChannels, const std::string& comment)
    : impl_(std::make_unique<Impl>()), path_(path), numChannels_(numChannels)
{
    // juce::File wants absolute paths; getChildFile() leaves absolute ones as they are.
    const juce::File file = juce::File::getCurrentWorkingDirectory().getChildFile(juce::String(path));
    if (file.isDirectory())
        throw std::runtime_error(path + ": cannot write a WAV file: it is a directory");
    if (!file.getParentDirectory().isDirectory())
        throw std::runtime_error(path + ": cannot write a WAV file: the folder does not exist");
    impl_->temporary = std::make_unique<juce::TemporaryFile>(file);
    auto stream = std::make_unique<juce::FileOutputStream>(impl_->temporary->getFile());
    if (!stream->openedOk())
        throw std::runtime_error(
            path + ": cannot write a WAV file: " + stream->getStatus().getErrorMessage().toStdString());

    juce::StringPairArray metadata;
    if (!comment.empty())
        metadata.set(juce::WavAudioFormat::riffInfoComment2, juce::String(comment));
    metadata.set(juce::WavAudioFormat::riffInfoSoftware, "rosin");

    juce::WavAudioFormat wav;
    // 32 bits selects IEEE float in JUCE's WAV writer; a discrete layout keeps a 5-channel probe from being
    // labelled as 5.0 surround.
    impl_->writer.reset(wav.createWriterFor(
        stream.get(), sampleRate, juce::AudioChannelSet::discreteChannels(numChannels), 32, metadata, 0));
    if (impl_->writer == nullptr)
        throw std::runtime_error(path + ": cannot write a WAV file with " + std::to_string(numChannels) +
                                 " channels at " + std::to_string(sampleRate) + " Hz");
    stream.release(); // now owned by the writer
}

WavWriter::~WavWriter() = default;

void WavWriter::write(const float* const* channels, int numSamples)
{
    if (impl_->writer == nullptr)
        throw std::logic_error(path_ + ": write after close");
    if (!impl_->writer->writeFromFloatArrays(channels, numChannels_, numSamples))
        throw std::runtime_error(path_ + ": write failed (disk full?)");
}

void WavWriter::close()
{
    if (impl_->writer == nullptr)
        return;
    const bool flushed = impl_->writer->flush();
    impl_->writer.reset(); // the destructor rewrites the header with the final length
    if (!flushed)
        throw std::runtime_error(path_ + ": could not finish the WAV file");
    if (!impl_->temporary->overwriteTargetFileWithTemporary())
        throw std::runtime_error(path_ + ": could not replace the file with the finished render");
}

} // namespace rosin::cli
