#include "core/analysis/RegimeClassifier.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

namespace rosin::analysis
{

namespace t = regime_thresholds;

namespace
{
std::size_t windowEnd(AnalysisWindow w, std::size_t length)
{
    return w.end == 0 ? length : std::min(w.end, length);
}

std::vector<std::size_t> inWindow(const std::vector<std::size_t>& onsets, std::size_t begin, std::size_t end)
{
    std::vector<std::size_t> out;
    std::copy_if(onsets.begin(), onsets.end(), std::back_inserter(out),
                 [&](std::size_t k) { return k >= begin && k < end; });
    return out;
}

struct Pattern
{
    int slipsPerCycle = 0;
    double period = 0.0; ///< samples
    double error = 0.0;  ///< rms(Delta_{i+k} - Delta_i) / period
    double share = 0.0;  ///< share of pairs with |Delta_{i+k} - Delta_i| < kPatternTolerance period
};

double median(std::vector<double> v)
{
    const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    return *mid;
}

// How well the intervals d repeat after k of them, for a cycle of `period` samples.
void patternFit(const std::vector<double>& d, std::size_t k, double period, double& error, double& share)
{
    double squares = 0.0;
    std::size_t pairs = 0, matching = 0;
    for (std::size_t i = 0; i + k < d.size(); ++i, ++pairs)
    {
        const double e = std::abs(d[i + k] - d[i]) / period;
        squares += e * e;
        matching += e < t::kPatternTolerance ? 1 : 0;
    }
    error = pairs > 0 ? std::sqrt(squares / static_cast<double>(pairs)) : 0.0;
    share = pairs > 0 ? static_cast<double>(matching) / static_cast<double>(pairs) : 0.0;
}

// The smallest k for which the onset intervals repeat k intervals later. Fills RegimeAnalysis's interval
// statistics on the way.
Pattern findPattern(const std::vector<std::size_t>& onsets, RegimeAnalysis& r)
{
    Pattern none;
    if (onsets.size() < 2)
        return none;
    std::vector<double> d;
    for (std::size_t i = 1; i < onsets.size(); ++i)
        d.push_back(static_cast<double>(onsets[i] - onsets[i - 1]));
    double mean = 0.0, squares = 0.0;
    for (double x : d)
        mean += x, squares += x * x;
    mean /= static_cast<double>(d.size());
    const double variance = std::max(0.0, squares / static_cast<double>(d.size()) - mean * mean);
    r.intervalCv = mean > 0.0 ? std::sqrt(variance) / mean : 0.0;
    patternFit(d, 1, mean, r.patternError, r.patternShare);

    for (std::size_t k = 1; k <= static_cast<std::size_t>(t::kMaxSlipsPerCycle); ++k)
    {
        if (d.size() / k < static_cast<std::size_t>(t::kMinCycles))
            break;
        std::vector<double> cycles;
        for (std::size_t i = 0; i + k < onsets.size(); ++i)
            cycles.push_back(static_cast<double>(onsets[i + k] - onsets[i]));
        Pattern p;
        p.slipsPerCycle = static_cast<int>(k);
        p.period = median(cycles);
        patternFit(d, k, p.period, p.error, p.share);
        if (p.share >= t::kMinPatternShare)
            return p;
    }
    return none;
}

// Least-squares rise across [begin, end) and the rms of the residual about the line.
void lineTrend(const std::vector<double>& x, std::size_t begin, std::size_t end, double& rise,
               double& residual)
{
    const double n = static_cast<double>(end - begin);
    double st = 0.0, sx = 0.0, stt = 0.0, stx = 0.0;
    for (std::size_t k = begin; k < end; ++k)
    {
        const double tk = static_cast<double>(k - begin);
        st += tk, sx += x[k], stt += tk * tk, stx += tk * x[k];
    }
    const double denominator = n * stt - st * st;
    const double slope = denominator > 0.0 ? (n * stx - st * sx) / denominator : 0.0;
    const double intercept = (sx - slope * st) / n;
    double squares = 0.0;
    for (std::size_t k = begin; k < end; ++k)
        squares += std::pow(x[k] - (intercept + slope * static_cast<double>(k - begin)), 2);
    rise = slope * (n - 1.0);
    residual = std::sqrt(squares / n);
}

// Labels a window that has onsets (and, for the state path, is not constant slipping).
RegimeAnalysis labelFromOnsets(const std::vector<std::size_t>& onsets, const std::vector<double>& force,
                               double P, std::size_t begin, std::size_t end, RegimeAnalysis r)
{
    r.onsetCount = onsets.size();
    if (onsets.size() >= 2)
        r.slipsPerPeriod =
            static_cast<double>(onsets.size() - 1) * P / static_cast<double>(onsets.back() - onsets.front());
    const Pattern pattern = findPattern(onsets, r);
    if (pattern.slipsPerCycle == 0)
    {
        r.regime = Regime::Raucous; // no repeating pattern, or too few slips to show one
        return r;
    }
    r.slipsPerCycle = pattern.slipsPerCycle;
    r.measuredPeriod = pattern.period;
    r.patternError = pattern.error;
    r.patternShare = pattern.share;
    r.pitchCents = 1200.0 * std::log2(P / pattern.period);
    r.withinReferencePitch = std::abs(pattern.period / P - 1.0) < t::kReferencePeriodTolerance;
    const bool haveForce = force.size() >= end && end > begin;
    if (haveForce)
    {
        r.sawtoothness = sawtoothness(force, begin, end, pattern.period);
        r.autocorrelation = autocorrelationAt(force, begin, end, pattern.period);
        if (r.autocorrelation < t::kMinAutocorrelation) // false for NaN
        {
            r.regime = Regime::Raucous; // the slips repeat but the waveform does not
            return r;
        }
    }

    const double ratio = pattern.period / P;
    const int k = pattern.slipsPerCycle;
    if (ratio >= t::kAlfMinPeriodRatio)
        r.regime = Regime::AnomalousLowFrequency;
    else if (ratio > 1.0 - t::kPeriodTolerance)
    {
        if (k == 1)
        {
            const bool sawtooth = std::isnan(r.sawtoothness) ||
                                  (r.sawtoothness >= t::kSawtoothMin && r.sawtoothness <= t::kSawtoothMax);
            r.regime = sawtooth ? Regime::Helmholtz : Regime::SMotion;
        }
        else
            r.regime = k == 2 ? Regime::DoubleSlipping : Regime::MultipleSlipping;
    }
    else
    {
        // A faster pattern still counts as repeating with period P if P holds a whole number of its cycles.
        const double m = std::round(1.0 / ratio);
        if (m >= 2.0 && std::abs(m * ratio - 1.0) < t::kPeriodTolerance)
            r.regime = k * m <= 2.0 ? Regime::DoubleSlipping : Regime::MultipleSlipping;
        else
            r.regime = Regime::Raucous;
    }
    return r;
}
} // namespace

double sawtoothness(const std::vector<double>& x, std::size_t begin, std::size_t end, double periodSamples)
{
    end = std::min(end, x.size());
    const double nan = std::numeric_limits<double>::quiet_NaN();
    if (!(periodSamples > 0.0) || end <= begin)
        return nan;
    const double cycles = std::floor(static_cast<double>(end - begin) / periodSamples);
    if (cycles < 2.0)
        return nan;
    const auto n = static_cast<std::size_t>(std::round(cycles * periodSamples));
    double mean = 0.0;
    for (std::size_t j = 0; j < n; ++j)
        mean += x[begin + j];
    mean /= static_cast<double>(n);
    // The Hann window and the two harmonics' phasors advance by one fixed rotation per sample (no sine or
    // cosine per sample: this runs on every scan cell; the rounding over a window is ~1e-12).
    std::complex<double> F1, F2;
    const std::complex<double> windowStep = std::polar(1.0, 2.0 * M_PI / static_cast<double>(n));
    const std::complex<double> step1 = std::polar(1.0, -2.0 * M_PI / periodSamples), step2 = step1 * step1;
    std::complex<double> windowPhasor = 1.0, e1 = 1.0, e2 = 1.0;
    for (std::size_t j = 0; j < n; ++j)
    {
        const double v = (0.5 - 0.5 * windowPhasor.real()) * (x[begin + j] - mean);
        F1 += v * e1;
        F2 += v * e2;
        windowPhasor *= windowStep;
        e1 *= step1;
        e2 *= step2;
    }
    return std::abs(F2) > 0.0 ? std::abs(F1) / (2.0 * std::abs(F2)) : 1e9;
}

double autocorrelationAt(const std::vector<double>& x, std::size_t begin, std::size_t end, double lagSamples)
{
    end = std::min(end, x.size());
    const auto lag = static_cast<std::size_t>(std::max(0.0, std::round(lagSamples)));
    if (lag == 0 || end <= begin + lag + 1)
        return std::numeric_limits<double>::quiet_NaN();
    double mean = 0.0;
    for (std::size_t k = begin; k < end; ++k)
        mean += x[k];
    mean /= static_cast<double>(end - begin);
    double ab = 0.0, aa = 0.0, bb = 0.0;
    for (std::size_t k = begin; k + lag < end; ++k)
    {
        const double a = x[k] - mean, b = x[k + lag] - mean;
        ab += a * b, aa += a * a, bb += b * b;
    }
    return aa > 0.0 && bb > 0.0 ? ab / std::sqrt(aa * bb) : 1.0;
}

RegimeAnalysis classifyFromEpisodes(const std::vector<SlipEpisode>& episodes, double slipFraction,
                                    std::size_t signalLength, const std::vector<double>& bridgeForce,
                                    double periodSamples, AnalysisWindow window)
{
    RegimeAnalysis r;
    r.slipFraction = slipFraction;
    const std::size_t end = windowEnd(window, signalLength);
    const auto onsets = inWindow(onsetsOf(episodes), window.begin, end);
    r.onsetCount = onsets.size();
    if (slipFraction >= t::kConstantSlippingFraction)
    {
        r.regime = Regime::ConstantSlipping;
        return r;
    }
    if (onsets.empty())
    {
        // Sliding samples without an onset: the window sits inside one long slip that began before it.
        r.regime = slipFraction > 0.0 ? Regime::ConstantSlipping : Regime::NoSlip;
        return r;
    }
    return labelFromOnsets(onsets, bridgeForce, periodSamples, window.begin, end, r);
}

RegimeAnalysis classifyFromState(const std::vector<bool>& sticking, const std::vector<double>& bridgeForce,
                                 double periodSamples, AnalysisWindow window)
{
    const std::size_t end = windowEnd(window, sticking.size());
    return classifyFromEpisodes(slipEpisodesFromState(sticking), slipFraction(sticking, window.begin, end),
                                sticking.size(), bridgeForce, periodSamples, window);
}

RegimeAnalysis classifyFromVoice(const std::vector<physics::VoiceSample>& samples, double periodSamples,
                                 AnalysisWindow window)
{
    const auto [force, sticking] = forceAndState(samples);
    const std::size_t end = windowEnd(window, samples.size());
    return classifyFromEpisodes(flybacksOnly(slipEpisodesFromVoice(samples)),
                                slipFraction(sticking, window.begin, end), samples.size(), force,
                                periodSamples, window);
}

RegimeAnalysis classifyFromBridgeForce(const std::vector<double>& bridgeForce, double periodSamples,
                                       AnalysisWindow window, const ForceOnsetOptions& options)
{
    if (windowEnd(window, bridgeForce.size()) <= window.begin)
        return {};
    return classifyFromForceOnsets(slipOnsetsFromBridgeForce(bridgeForce, periodSamples, options),
                                   bridgeForce, periodSamples, window);
}

RegimeAnalysis classifyFromForceOnsets(const std::vector<std::size_t>& allOnsets,
                                       const std::vector<double>& bridgeForce, double periodSamples,
                                       AnalysisWindow window)
{
    RegimeAnalysis r;
    const std::size_t end = windowEnd(window, bridgeForce.size());
    if (end <= window.begin)
        return r;
    const auto onsets = inWindow(allOnsets, window.begin, end);
    if (onsets.empty())
    {
        double rise = 0.0, residual = 0.0;
        lineTrend(bridgeForce, window.begin, end, rise, residual);
        r.regime =
            rise > 0.0 && rise > t::kDragTrendFactor * residual ? Regime::NoSlip : Regime::ConstantSlipping;
        return r;
    }
    return labelFromOnsets(onsets, bridgeForce, periodSamples, window.begin, end, r);
}

} // namespace rosin::analysis
