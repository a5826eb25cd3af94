#pragma once
// A WAV file reduced to the chunks a sample reader needs. JUCE's WAV reader parses every metadata chunk it
// meets (iXML, aXML, bext, cue, ...); fuzzing found its XML parser reading past the end of a damaged iXML
// chunk (a heap over-read, JUCE 7.0.5). A measured trial needs none of that metadata, so JUCE sees only a
// RIFF (or RF64, with a ds64 chunk) header whose sizes say what findWavDataChunk found, the file's first
// "fmt " chunk, and the data, which ends the stream.
#include <memory>

#include <juce_core/juce_core.h>

#include "lab/discovery/io/WavDataChunk.h"

namespace rosin::discovery
{

/// A stream holding `file`'s essential chunks, for juce::WavAudioFormat::createReaderFor. nullptr when the
/// file cannot be opened.
std::unique_ptr<juce::InputStream> openWavEssentials(const juce::File& file, const WavDataChunk& chunk);

} // namespace rosin::discovery
