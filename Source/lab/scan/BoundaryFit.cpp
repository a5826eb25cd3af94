#include "lab/scan/BoundaryFit.h"

#include <cmath>

namespace rosin::scan
{

namespace
{
struct Run
{
    std::size_t first = 0, length = 0;
};

// Longest run of Helmholtz cells in one beta column (force ascending), the lowest of equal runs.
Run longestRun(const ScanSpec& spec, const std::vector<CellResult>& results, std::size_t iBeta)
{
    Run best, current;
    for (std::size_t i = 0; i < spec.forces.size(); ++i)
    {
        const bool helmholtz = results[cellIndex(spec, {iBeta, i, 0})].regime == analysis::Regime::Helmholtz;
        if (!helmholtz)
        {
            current.length = 0;
            continue;
        }
        if (current.length == 0)
            current.first = i;
        ++current.length;
        if (current.length > best.length)
            best = current;
    }
    return best;
}
} // namespace

HelmholtzEdges helmholtzEdges(const ScanSpec& spec, const std::vector<CellResult>& results)
{
    HelmholtzEdges edges;
    const auto& F = spec.forces;
    for (std::size_t b = 0; b < spec.betas.size(); ++b)
    {
        const Run run = longestRun(spec, results, b);
        if (run.length == 0)
            continue;
        const std::size_t last = run.first + run.length - 1;
        if (run.first > 0)
            edges.lower.push_back({spec.betas[b], std::sqrt(F[run.first - 1] * F[run.first])});
        if (last + 1 < F.size())
            edges.upper.push_back({spec.betas[b], std::sqrt(F[last] * F[last + 1])});
    }
    return edges;
}

std::optional<LineFit> fitLogLog(const std::vector<BoundaryPoint>& points)
{
    const double n = static_cast<double>(points.size());
    double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
    for (const auto& p : points)
    {
        const double x = std::log10(p.beta), y = std::log10(p.force);
        sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    const double denominator = n * sxx - sx * sx;
    if (points.size() < 2 || !(denominator > 1e-12 * n * n))
        return std::nullopt;
    LineFit fit;
    fit.slope = (n * sxy - sx * sy) / denominator;
    fit.intercept = (sy - fit.slope * sx) / n;
    fit.points = points.size();
    return fit;
}

} // namespace rosin::scan
