#pragma once
// The WAV file of one trial: IEEE float 32-bit, one channel per entry of the dataset's "channels", values
// in physical units. JUCE does the WAV format; this header is JUCE-free so its users need no JUCE headers.
#include <cstddef>
#include <string>
#include <vector>

#include "lab/discovery/Dataset.h"

namespace rosin::discovery
{

struct TrialSignals
{
    int sampleRate = 0;
    std::vector<Channel> channels;            ///< the dataset's, in file order
    std::vector<std::vector<double>> samples; ///< samples[c][n], in the unit of channels[c]

    std::size_t frames() const { return samples.empty() ? 0 : samples.front().size(); }
    /// The samples of the channel of that name; throws std::out_of_range if the dataset has no such channel.
    const std::vector<double>& channel(const std::string& name) const;
};

/// Reads the trial's file. Throws DatasetError naming the WAV file and what was expected when it is missing,
/// not a WAV file, not IEEE float 32-bit, has another channel count or sample rate than dataset.json says,
/// holds no samples, is truncated (shorter than its header says: rejected, never zero-filled) or holds a
/// non-finite value; a file path outside the dataset folder names dataset.json and "trials[i].file".
TrialSignals readTrialSignals(const Dataset& dataset, const Trial& trial);

/// Writes the trial's file under dataset.folder (creating trials/ as needed) as IEEE float 32-bit at
/// dataset.sampleRate. `channels` must match dataset.channels in number and be of one non-zero length; values
/// are rounded to float. Written to a temporary file and renamed, so a failure leaves no partial file.
/// Throws DatasetError on a mismatch, a non-finite value or a write failure.
void writeTrialSignals(const Dataset& dataset, const Trial& trial,
                       const std::vector<std::vector<double>>& channels);

} // namespace rosin::discovery
