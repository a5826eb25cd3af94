#pragma once
// The least-squares line through samples x[begin, end) against their index, with the index centred so the
// sums stay well conditioned over long records.
#include <cstddef>
#include <vector>

namespace rosin::analysis
{

struct LineFit
{
    double centre = 0.0; ///< the mean index of the window
    double mean = 0.0;   ///< the line's value at `centre` (the samples' mean)
    double slope = 0.0;  ///< per sample
    double at(double k) const noexcept { return mean + slope * (k - centre); }
};

/// Requires end > begin + 1.
LineFit fitLine(const std::vector<double>& x, std::size_t begin, std::size_t end);

} // namespace rosin::analysis
