#pragma once
// The significance test of an effect's held-out improvement: a paired sign-flip randomisation test on the
// per-trial differences d_i = e_i(before) - e_i(with the effect) of normalised squared errors. Under "the
// effect does not help", each d_i is as likely positive as negative; the one-sided p-value is the share of
// random sign assignments whose mean is at least the observed mean (with the observed one counted, so
// p >= 1 / (flips + 1)). Deterministic for a seed. JUCE-free.
#include <cstdint>
#include <vector>

namespace rosin::discovery
{

struct PairedTestResult
{
    double meanDifference = 0.0;
    double pValue = 1.0;
    std::size_t pairs = 0;
};

PairedTestResult signFlipTest(const std::vector<double>& differences, std::uint64_t seed, int flips = 19999);

} // namespace rosin::discovery
