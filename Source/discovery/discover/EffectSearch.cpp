#include "EffectSearch.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "ModelRuns.h"
#include "PairedTest.h"

namespace rosin::discovery
{

namespace
{
constexpr int kGridOne = 7, kGridTwo = 5, kGoldenSteps = 5;

// Parameter value <-> search coordinate (log where the catalog says so).
double toCoordinate(const EffectParameter& p, double v)
{
    return p.logarithmic ? std::log(v) : v;
}
double fromCoordinate(const EffectParameter& p, double x)
{
    return std::clamp(p.logarithmic ? std::exp(x) : x, p.min, p.max);
}

class Fitter
{
  public:
    Fitter(const SearchInputs& in, const SimulationModel& base, const Effect& effect)
        : in_(in), base_(base), effect_(effect)
    {
    }

    double objective(const std::vector<double>& values)
    {
        auto it = memo_.find(values);
        if (it != memo_.end())
            return it->second;
        SimulationModel m = base_;
        applyEffect(effect_, values, m);
        const auto sim = simulateFeatures(m, *in_.dataset, in_.training, in_.seconds, in_.threads);
        const double o = measureGap(in_.training, in_.measured, sim, in_.scatter).objective;
        ++evaluations;
        return memo_[values] = o;
    }

    std::vector<double> fit()
    {
        const auto& ps = effect_.parameters;
        std::vector<std::vector<double>> axes;
        for (const auto& p : ps)
        {
            std::vector<double> axis;
            if (!p.choices.empty())
                for (std::size_t c = 0; c < p.choices.size(); ++c)
                    axis.push_back(static_cast<double>(c));
            else
            {
                const int n = ps.size() == 1 ? kGridOne : kGridTwo;
                const double a = toCoordinate(p, p.min), b = toCoordinate(p, p.max);
                for (int k = 0; k < n; ++k)
                    axis.push_back(fromCoordinate(p, a + (b - a) * k / (n - 1)));
            }
            axes.push_back(axis);
        }
        std::vector<double> best(ps.size()), point(ps.size());
        double bestValue = 1e300;
        std::vector<std::size_t> index(ps.size(), 0);
        for (;;)
        {
            for (std::size_t j = 0; j < ps.size(); ++j)
                point[j] = axes[j][index[j]];
            if (const double o = objective(point); o < bestValue)
            {
                bestValue = o;
                best = point;
            }
            std::size_t j = 0;
            while (j < ps.size() && ++index[j] == axes[j].size())
                index[j++] = 0;
            if (j == ps.size())
                break;
        }
        for (std::size_t j = 0; j < ps.size(); ++j)
            if (ps[j].choices.empty())
                best = golden(best, j, axes[j]);
        return best;
    }

    int evaluations = 0;

  private:
    std::vector<double> golden(std::vector<double> best, std::size_t j, const std::vector<double>& axis)
    {
        const auto& p = effect_.parameters[j];
        const double step = (toCoordinate(p, axis.back()) - toCoordinate(p, axis.front())) /
                            static_cast<double>(axis.size() - 1);
        const double centre = toCoordinate(p, best[j]);
        double a = std::max(toCoordinate(p, p.min), centre - step);
        double b = std::min(toCoordinate(p, p.max), centre + step);
        auto at = [&](double x)
        {
            std::vector<double> v = best;
            v[j] = fromCoordinate(p, x);
            return objective(v);
        };
        const double r = 0.5 * (std::sqrt(5.0) - 1.0);
        double c = b - r * (b - a), d = a + r * (b - a);
        double fc = at(c), fd = at(d);
        for (int k = 0; k < kGoldenSteps - 2; ++k)
        {
            if (fc < fd)
            {
                b = d;
                d = c;
                fd = fc;
                c = b - r * (b - a);
                fc = at(c);
            }
            else
            {
                a = c;
                c = d;
                fc = fd;
                d = a + r * (b - a);
                fd = at(d);
            }
        }
        const double bestSoFar = objective(best);
        const double x = fc < fd ? c : d;
        if (std::min(fc, fd) < bestSoFar)
            best[j] = fromCoordinate(p, x);
        return best;
    }

    const SearchInputs& in_;
    const SimulationModel& base_;
    const Effect& effect_;
    std::map<std::vector<double>, double> memo_;
};

// Fitted values are reported (and adopted) to 3 significant digits: the fit is not finer than that.
double roundToThreeDigits(const EffectParameter& p, double v)
{
    if (!p.choices.empty() || v == 0.0)
        return v;
    const double scale = std::pow(10.0, 2 - static_cast<int>(std::floor(std::log10(std::abs(v)))));
    return std::clamp(std::round(v * scale) / scale, p.min, p.max);
}

EffectScore score(const SearchInputs& in, const SimulationModel& current,
                  const std::vector<TrialFeatures>& currentHeldOut, const Effect& effect, double alpha)
{
    EffectScore s;
    s.effect = &effect;
    Fitter fitter(in, current, effect);
    s.values = fitter.fit();
    for (std::size_t j = 0; j < s.values.size(); ++j)
        s.values[j] = roundToThreeDigits(effect.parameters[j], s.values[j]);
    s.evaluations = fitter.evaluations;
    SimulationModel m = current;
    applyEffect(effect, s.values, m);
    const auto sim = simulateFeatures(m, *in.dataset, in.heldOut, in.seconds, in.threads);
    s.heldOutBefore = measureGap(in.heldOut, in.measured, currentHeldOut, in.scatter);
    s.heldOutAfter = measureGap(in.heldOut, in.measured, sim, in.scatter);
    const auto e0 = objectiveShares(in.heldOut, in.measured, currentHeldOut, in.scatter);
    const auto e1 = objectiveShares(in.heldOut, in.measured, sim, in.scatter);
    std::vector<double> d;
    double before = 0.0, after = 0.0;
    for (std::size_t i = 0; i < e0.size(); ++i)
    {
        before += e0[i];
        after += e1[i];
        if (e0[i] != 0.0 || e1[i] != 0.0)
            d.push_back(e0[i] - e1[i]);
    }
    s.heldOutGain = before > 0.0 ? 1.0 - after / before : 0.0;
    s.pValue = signFlipTest(d, in.seed + effectIndex(effect)).pValue;
    s.significant = s.pValue < alpha && s.heldOutGain >= kMinRelativeGain;
    return s;
}
} // namespace

void splitTrials(const ScanGrid& grid, std::vector<std::size_t>& training, std::vector<std::size_t>& heldOut)
{
    for (const auto& cell : grid.cells)
        for (std::size_t t : cell.trials)
            ((cell.beta + cell.force + cell.motion) % 2 == 0 ? training : heldOut).push_back(t);
    std::sort(training.begin(), training.end());
    std::sort(heldOut.begin(), heldOut.end());
}

SearchResult searchEffects(const SearchInputs& in, const SimulationModel& baseline)
{
    SearchResult result;
    result.model = baseline;
    std::vector<const Effect*> remaining;
    for (const auto& e : effectCatalog())
        remaining.push_back(&e);
    while (result.steps.size() < kMaxEffects && !remaining.empty())
    {
        const auto currentHeldOut =
            simulateFeatures(result.model, *in.dataset, in.heldOut, in.seconds, in.threads);
        // After an adopted effect: nothing left to explain when the held-out gap is within the scatter.
        if (!result.steps.empty() &&
            measureGap(in.heldOut, in.measured, currentHeldOut, in.scatter).overall <= 0.0)
            break;
        const double alpha = kSignificanceLevel / static_cast<double>(remaining.size());
        std::vector<EffectScore> tried;
        for (const Effect* e : remaining)
        {
            tried.push_back(score(in, result.model, currentHeldOut, *e, alpha));
            if (in.log)
            {
                const auto& s = tried.back();
                char line[200];
                std::snprintf(
                    line, sizeof(line), "  step %zu: %-21s held-out gain %+6.1f %%, p = %.2g (%d fits)\n",
                    result.steps.size() + 1, e->name.c_str(), 100.0 * s.heldOutGain, s.pValue, s.evaluations);
                *in.log << line << std::flush;
            }
        }
        const EffectScore* best = nullptr;
        for (const auto& s : tried)
            if (s.significant && (!best || s.heldOutGain > best->heldOutGain))
                best = &s;
        if (!best)
        {
            result.lastTried = tried;
            result.lastAlpha = alpha;
            break;
        }
        SearchStep step;
        step.chosen = *best;
        step.tried = tried;
        step.alpha = alpha;
        applyEffect(*best->effect, best->values, result.model);
        step.model = result.model;
        remaining.erase(std::find(remaining.begin(), remaining.end(), best->effect));
        result.steps.push_back(std::move(step));
    }
    return result;
}

std::string describeEvidence(const EffectScore& s, double alpha)
{
    std::string text = "on the held-out trials (fitted on the other half): ";
    bool first = true;
    for (std::size_t f = 0; f < kFeatureCount; ++f)
    {
        if (s.heldOutBefore.count[f] < kMinTrialsForGap)
            continue;
        const double b = std::sqrt(s.heldOutBefore.meanSquare[f]),
                     a = std::sqrt(s.heldOutAfter.meanSquare[f]);
        if (std::abs(b - a) < 0.1 * std::max(b, 1.0))
            continue;
        char part[160];
        std::snprintf(part, sizeof(part), "%s%s rms difference %.2g -> %.2g sigma", first ? "" : ", ",
                      featureName(f), b, a);
        text += part;
        first = false;
    }
    if (first)
        text += "no single feature changed by more than 10 %";
    char tail[240];
    std::snprintf(tail, sizeof(tail),
                  "; the mean normalised squared error fell by %.0f %%; paired sign-flip test p = %.2g "
                  "(threshold %.2g)",
                  100.0 * s.heldOutGain, s.pValue, alpha);
    return text + tail;
}

} // namespace rosin::discovery
