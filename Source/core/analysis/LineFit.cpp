#include "core/analysis/LineFit.h"

namespace rosin::analysis
{

LineFit fitLine(const std::vector<double>& x, std::size_t begin, std::size_t end)
{
    LineFit f;
    const double n = static_cast<double>(end - begin);
    f.centre = (static_cast<double>(begin) + static_cast<double>(end - 1)) / 2.0;
    double sx = 0.0, sux = 0.0, suu = 0.0;
    for (std::size_t k = begin; k < end; ++k)
    {
        const double u = static_cast<double>(k) - f.centre;
        sx += x[k];
        sux += u * x[k];
        suu += u * u;
    }
    f.mean = sx / n;
    f.slope = sux / suu;
    return f;
}

} // namespace rosin::analysis
