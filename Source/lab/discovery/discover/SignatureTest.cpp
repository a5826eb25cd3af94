#include "lab/discovery/discover/SignatureTest.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <Eigen/Dense>

namespace rosin::discovery
{
namespace
{
/// The grid coordinates (log beta, log force, log motion) of each dataset trial on the grid; NaN elsewhere.
std::vector<std::array<double, 3>> logCoordinates(const ScanGrid& grid, std::size_t trialCount)
{
    std::vector<std::array<double, 3>> u(trialCount, {NAN, NAN, NAN});
    for (const GridCell& c : grid.cells)
        for (std::size_t t : c.trials)
            if (t < trialCount)
                u[t] = {std::log(grid.betas[c.beta]), std::log(grid.forces[c.force]),
                        grid.motion.empty() ? 0.0 : std::log(grid.motion[c.motion])};
    return u;
}

struct FeatureRows
{
    std::vector<double> r, g, w;
    std::vector<std::array<double, 3>> u;
};

FeatureRows rowsOf(std::size_t f, const std::vector<std::size_t>& trials,
                   const std::vector<std::array<double, 3>>& u, const std::vector<TrialFeatures>& measured,
                   const std::vector<TrialFeatures>& current, const std::vector<TrialFeatures>& candidate,
                   const FeatureScatter& scatter)
{
    FeatureRows rows;
    for (std::size_t t : trials)
    {
        const auto &m = measured[t][f], &c = current[t][f], &e = candidate[t][f];
        const double sigma = scatter.trialSigma(t, f);
        if (!m || !c || !e || !(sigma > 0.0) || !std::isfinite(u[t][0]))
            continue;
        rows.r.push_back(std::clamp((*m - *c) / sigma, -kSignatureClip, kSignatureClip));
        rows.g.push_back(std::clamp((*e - *c) / sigma, -kSignatureClip, kSignatureClip));
        rows.w.push_back(1.0 / sigma);
        rows.u.push_back(u[t]);
    }
    return rows;
}

/// The weighted design (1, and each axis that varies among the rows) / sigma.
Eigen::MatrixXd biasDesign(const FeatureRows& rows)
{
    const std::size_t n = rows.r.size();
    std::vector<int> axes;
    for (int a = 0; a < 3; ++a)
        if (std::any_of(rows.u.begin(), rows.u.end(), [&](const auto& v) { return v[a] != rows.u[0][a]; }))
            axes.push_back(a);
    Eigen::MatrixXd X(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(1 + axes.size()));
    for (std::size_t i = 0; i < n; ++i)
    {
        const auto row = static_cast<Eigen::Index>(i);
        X(row, 0) = rows.w[i];
        for (std::size_t a = 0; a < axes.size(); ++a)
            X(row, static_cast<Eigen::Index>(1 + a)) =
                rows.w[i] * rows.u[i][static_cast<std::size_t>(axes[a])];
    }
    return X;
}
} // namespace

SignatureScore signatureScore(const std::vector<std::size_t>& trials, const ScanGrid& grid,
                              const std::vector<TrialFeatures>& measured,
                              const std::vector<TrialFeatures>& current,
                              const std::vector<TrialFeatures>& candidate, const FeatureScatter& scatter)
{
    const auto u = logCoordinates(grid, measured.size());
    double along = 0.0, left = 0.0, raw = 0.0;
    SignatureScore s;
    for (std::size_t f = 0; f < kFeatureCount; ++f)
    {
        if (isCategorical(f))
            continue;
        const FeatureRows rows = rowsOf(f, trials, u, measured, current, candidate, scatter);
        const Eigen::MatrixXd X = biasDesign(rows);
        if (rows.r.size() <= static_cast<std::size_t>(X.cols()) + 1)
            continue; // no residual freedom beyond the bias
        const Eigen::Map<const Eigen::VectorXd> r(rows.r.data(), static_cast<Eigen::Index>(rows.r.size()));
        const Eigen::Map<const Eigen::VectorXd> g(rows.g.data(), static_cast<Eigen::Index>(rows.g.size()));
        const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(X);
        const Eigen::VectorXd rp = r - X * qr.solve(r);
        const Eigen::VectorXd gp = g - X * qr.solve(g);
        along += gp.dot(rp);
        left += gp.squaredNorm();
        raw += g.squaredNorm();
        s.pairs += rows.r.size();
    }
    // A signature the trends absorb to rounding carries no direction of its own.
    if (left > 1e-12 * raw)
        s.z = along / std::sqrt(left);
    if (raw > 0.0)
        s.beyondTrends = left / raw;
    return s;
}

} // namespace rosin::discovery
