#include "lab/discovery/discover/PairedTest.h"

#include <cmath>
#include <random>

namespace rosin::discovery
{

PairedTestResult signFlipTest(const std::vector<double>& d, std::uint64_t seed, int flips)
{
    PairedTestResult r;
    r.pairs = d.size();
    if (d.empty())
        return r;
    double sum = 0.0;
    for (double x : d)
        sum += x;
    r.meanDifference = sum / static_cast<double>(d.size());
    std::mt19937_64 random(seed ^ 0x5157a7e5u);
    int atLeast = 0;
    for (int k = 0; k < flips; ++k)
    {
        double s = 0.0;
        for (double x : d)
            s += (random() & 1u) ? x : -x;
        if (s >= sum - 1e-12 * std::abs(sum))
            ++atLeast;
    }
    r.pValue = (1.0 + atLeast) / (1.0 + flips);
    return r;
}

} // namespace rosin::discovery
