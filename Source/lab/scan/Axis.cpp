#include "lab/scan/Axis.h"

#include <cmath>

namespace rosin::scan
{

std::vector<double> linearAxis(double first, double last, std::size_t n)
{
    std::vector<double> v(n);
    for (std::size_t i = 0; i < n; ++i)
        v[i] = n == 1 ? first : first + (last - first) * static_cast<double>(i) / static_cast<double>(n - 1);
    // The last value exactly as given (no rounding of first + (last - first)).
    if (n > 1)
        v.back() = last;
    return v;
}

std::vector<double> logAxis(double first, double last, std::size_t n)
{
    std::vector<double> v(n);
    const double ratio = std::log(last / first);
    for (std::size_t i = 0; i < n; ++i)
        v[i] = n == 1 ? first : first * std::exp(ratio * static_cast<double>(i) / static_cast<double>(n - 1));
    if (n > 1)
        v.back() = last;
    return v;
}

} // namespace rosin::scan
