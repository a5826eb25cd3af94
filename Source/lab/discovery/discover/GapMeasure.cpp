#include "lab/discovery/discover/GapMeasure.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace rosin::discovery
{

double robustLoss(double z) noexcept
{
    return kStudentNu * std::log1p(z * z / kStudentNu);
}

double nullLoss() noexcept
{
    // Simpson's rule over z in [-12, 12] (the normal tail beyond carries < 1e-30 of the weight).
    static const double value = []
    {
        constexpr int n = 4800;
        constexpr double lo = -12.0, h = 24.0 / n;
        double sum = 0.0;
        for (int i = 0; i <= n; ++i)
        {
            const double z = lo + h * i;
            const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
            sum += w * robustLoss(z) * std::exp(-0.5 * z * z);
        }
        return sum * h / 3.0 / std::sqrt(2.0 * std::numbers::pi);
    }();
    return value;
}

std::optional<double> normalisedDifference(std::size_t feature, const std::optional<double>& measured,
                                           const std::optional<double>& simulated, double sigma,
                                           HelmholtzTrials trials)
{
    const bool unseen = !measured || (trials == HelmholtzTrials::BothSides && !simulated);
    if (std::isnan(sigma) || (unseen && describesHelmholtzMotion(feature)))
        return std::nullopt;
    if (measured && simulated && isCategorical(feature))
        return *measured == *simulated ? 0.0 : std::min(kMissingZ, 1.0 / std::sqrt(sigma));
    if (measured && simulated)
        return (*measured - *simulated) / sigma;
    if (measured)
        return kMissingZ;
    if (simulated)
        return -kMissingZ;
    return std::nullopt;
}

namespace
{
struct Compared
{
    double z, loss;
};

// z and rho of feature f in trial t, with the reference rule of MeasuredSide (GapMeasure.h).
std::optional<Compared> compare(std::size_t f, std::size_t t, const std::vector<TrialFeatures>& measured,
                                const std::vector<TrialFeatures>& simulated, const FeatureScatter& scatter,
                                HelmholtzTrials helmholtz, const std::vector<TrialFeatures>& reference)
{
    const double sigma = scatter.trialSigma(t, f);
    const auto z = normalisedDifference(f, measured[t][f], simulated[t][f], sigma, helmholtz);
    if (!z)
        return std::nullopt;
    Compared c{*z, robustLoss(*z)};
    if (!simulated[t][f] && t < reference.size() && describesHelmholtzMotion(f))
        if (const auto zr = normalisedDifference(f, measured[t][f], reference[t][f], sigma, helmholtz))
            c.loss = std::max(c.loss, robustLoss(*zr));
    return c;
}
} // namespace

GapSummary measureGap(const std::vector<std::size_t>& trials, const std::vector<TrialFeatures>& measured,
                      const std::vector<TrialFeatures>& simulated, const FeatureScatter& scatter,
                      HelmholtzTrials helmholtz, const std::vector<TrialFeatures>& reference)
{
    GapSummary g;
    for (std::size_t t : trials)
        for (std::size_t f = 0; f < kFeatureCount; ++f)
            if (const auto c = compare(f, t, measured, simulated, scatter, helmholtz, reference))
            {
                g.meanSquare[f] += std::min(c->z * c->z, kMissingZ * kMissingZ);
                g.meanLoss[f] += c->loss;
                ++g.count[f];
            }
    std::size_t used = 0;
    for (std::size_t f = 0; f < kFeatureCount; ++f)
    {
        if (g.count[f] > 0)
        {
            g.meanSquare[f] /= static_cast<double>(g.count[f]);
            g.meanLoss[f] /= static_cast<double>(g.count[f]);
        }
        g.gap[f] = g.count[f] > 0 ? std::sqrt(std::max(0.0, g.meanLoss[f] - nullLoss())) : 0.0;
        if (g.count[f] >= kMinTrialsForGap)
        {
            g.overall += g.gap[f];
            g.objective += g.meanLoss[f];
            ++used;
        }
    }
    if (used > 0)
    {
        g.overall /= static_cast<double>(used);
        g.objective /= static_cast<double>(used);
    }
    return g;
}

std::vector<double> objectiveShares(const std::vector<std::size_t>& trials,
                                    const std::vector<TrialFeatures>& measured,
                                    const std::vector<TrialFeatures>& simulated,
                                    const FeatureScatter& scatter,
                                    const std::vector<TrialFeatures>& reference)
{
    const GapSummary g = fitGap(trials, measured, simulated, scatter, reference);
    std::size_t used = 0;
    for (std::size_t f = 0; f < kFeatureCount; ++f)
        used += g.count[f] >= kMinTrialsForGap ? 1 : 0;
    std::vector<double> shares(trials.size(), 0.0);
    if (used == 0)
        return shares;
    for (std::size_t i = 0; i < trials.size(); ++i)
        for (std::size_t f = 0; f < kFeatureCount; ++f)
        {
            if (g.count[f] < kMinTrialsForGap)
                continue;
            const std::size_t t = trials[i];
            if (const auto c =
                    compare(f, t, measured, simulated, scatter, HelmholtzTrials::MeasuredSide, reference))
                shares[i] += c->loss / static_cast<double>(g.count[f] * used);
        }
    return shares;
}

GapSignificance gapSignificance(const GapSummary& gap)
{
    GapSignificance g;
    std::size_t tested = 0;
    for (std::size_t f = 0; f < kFeatureCount; ++f)
    {
        if (gap.count[f] < kMinTrialsForGap)
            continue;
        ++tested;
        const double n = static_cast<double>(gap.count[f]);
        const double x = gap.meanSquare[f] * n;
        const double spread = 2.0 / (9.0 * n);
        const double normal = (std::cbrt(x / n) - (1.0 - spread)) / std::sqrt(spread);
        const double p = 0.5 * std::erfc(normal / std::sqrt(2.0));
        if (p < g.pValue)
        {
            g.pValue = p;
            g.feature = f;
        }
    }
    g.pValue = std::min(1.0, g.pValue * static_cast<double>(std::max<std::size_t>(tested, 1)));
    return g;
}

namespace
{
std::string range(const std::vector<double>& axis, int half, const char* name, const char* unit)
{
    std::size_t lo = 0, hi = axis.size() - 1;
    if (axis.size() > 1)
    {
        const std::size_t mid = axis.size() / 2;
        if (half == 0)
            hi = mid - 1;
        else
            lo = mid;
    }
    char text[120];
    if (lo == hi)
        std::snprintf(text, sizeof(text), "%s %.4g%s", name, axis[lo], unit);
    else
        std::snprintf(text, sizeof(text), "%s %.4g-%.4g%s", name, axis[lo], axis[hi], unit);
    return text;
}
} // namespace

std::string whereLargest(std::size_t feature, const Dataset& dataset, const ScanGrid& grid,
                         const std::vector<std::size_t>& trials, const std::vector<TrialFeatures>& measured,
                         const std::vector<TrialFeatures>& simulated, const FeatureScatter& scatter)
{
    (void)dataset;
    std::vector<int> cellOf(measured.size(), -1);
    // Region code of each trial: bit 0 upper force half, bit 1 upper motion half, bit 2 upper beta half.
    auto upper = [](std::size_t index, std::size_t size) { return size > 1 && index >= size / 2 ? 1 : 0; };
    for (const auto& cell : grid.cells)
        for (std::size_t t : cell.trials)
            cellOf[t] = upper(cell.force, grid.forces.size()) |
                        (upper(cell.motion, std::max<std::size_t>(1, grid.motion.size())) << 1) |
                        (upper(cell.beta, grid.betas.size()) << 2);
    double sumLoss[8] = {}, sumSq[8] = {}, sum[8] = {};
    int n[8] = {}, differ[8] = {};
    for (std::size_t t : trials)
    {
        if (cellOf[t] < 0)
            continue;
        if (auto z = normalisedDifference(feature, measured[t][feature], simulated[t][feature],
                                          scatter.trialSigma(t, feature)))
        {
            sumLoss[cellOf[t]] += robustLoss(*z);
            sumSq[cellOf[t]] += *z * *z;
            sum[cellOf[t]] += *z;
            differ[cellOf[t]] += *z != 0.0 ? 1 : 0;
            ++n[cellOf[t]];
        }
    }
    int best = -1;
    for (int r = 0; r < 8; ++r)
        if (n[r] >= 2 && (best < 0 || sumLoss[r] / n[r] > sumLoss[best] / n[best]))
            best = r;
    if (best < 0)
        return "";
    std::string text = range(grid.forces, best & 1, "force", " N");
    if (!grid.motion.empty())
        text += ", " + range(grid.motion, (best >> 1) & 1,
                             grid.kind == ScanKind::Schelleng ? "bow speed" : "acceleration",
                             grid.kind == ScanKind::Schelleng ? " m/s" : " m/s^2");
    text += ", " + range(grid.betas, (best >> 2) & 1, "beta", "");
    const double meanZ = sum[best] / n[best];
    char tail[160];
    if (isCategorical(feature))
    {
        std::snprintf(tail, sizeof(tail), ": measured and model differ in %d of %d trials", differ[best],
                      n[best]);
        return text + tail;
    }
    std::snprintf(tail, sizeof(tail),
                  ": measured %s the model by %.2g sigma on average (rms %.2g sigma, %d trials)",
                  meanZ >= 0 ? "above" : "below", std::abs(meanZ), std::sqrt(sumSq[best] / n[best]), n[best]);
    return text + tail;
}

} // namespace rosin::discovery
