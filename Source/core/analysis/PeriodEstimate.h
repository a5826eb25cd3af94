#pragma once
// The period of a periodic stretch of a signal to a fraction of a sample. The regime classifier's period is
// the median of whole-sample onset intervals: at a cello D (300 samples at 44.1 kHz) one sample is 5.8
// cents, coarser than the pitch flattening a change of bow force makes ([Galluzzo2017]; [Notes §7]). Here:
// the normalised autocorrelation of the stretch at lags near a rough period, its highest lag refined by the
// parabola through it and its two neighbours, then the same at the lag of as many periods as fit in half the
// stretch, divided by their number.
#include <cstddef>
#include <optional>
#include <vector>

namespace rosin::analysis
{

/// The period in samples of x over [begin, end), searched within +-`searchShare` of `roughPeriod`; nullopt
/// when the stretch is shorter than three rough periods or the peak lies on the edge of the search.
std::optional<double> refinedPeriod(const std::vector<double>& x, std::size_t begin, std::size_t end,
                                    double roughPeriod, double searchShare = 0.05);

} // namespace rosin::analysis
