#pragma once
// The failed measurements of a synthetic dataset. A real scan has a few: the acquisition stopped early, or a
// loose connector dropped the signal for a moment. The spec keeps such trials with "valid": false (not
// scored), and a reader must cope with their files, so rosin synth-data writes a few of each kind.
#include <optional>
#include <string>
#include <vector>

#include "lab/discovery/SeededRandom.h"

namespace rosin::discovery
{

struct TrialFault
{
    enum class Kind
    {
        CutShort, ///< the record ends at `start` (a short file)
        Dropout   ///< every channel reads 0 from `start` for `length` (a full-length file)
    };
    Kind kind = Kind::CutShort;
    double start = 0.0;  ///< s
    double length = 0.0; ///< s (Dropout)
};

/// Share of trials that fail, and the least number of trials for which at least one does.
inline constexpr double kFailedShare = 0.025;
inline constexpr std::size_t kTrialsForOneFailure = 20;

/// How many of `trials` fail: round(2.5 %), at least one from 20 trials on, none below.
std::size_t failedTrialCount(std::size_t trials);
/// Which trials fail (ascending), drawn from the dataset's FaultChoice stream.
std::vector<std::size_t> chooseFailedTrials(std::size_t trials, std::uint64_t seed);
/// The fault of one failed trial of `seconds`, from its FaultDetail stream: cut short at 15-60 % of the
/// trial, or a 5-30 ms dropout starting between 10 % and 80 % of it.
TrialFault drawTrialFault(std::uint64_t seed, std::size_t trial, double seconds);

/// Applies the fault to the measured channels (each of one length).
void applyTrialFault(const TrialFault& fault, double sampleRate, std::vector<std::vector<double>>& channels);
/// "cut short at 0.12 s", "dropout 0.21-0.23 s".
std::string describeTrialFault(const TrialFault& fault);

} // namespace rosin::discovery
