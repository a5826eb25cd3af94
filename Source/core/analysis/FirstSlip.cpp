#include "core/analysis/FirstSlip.h"

#include <algorithm>
#include <cmath>

#include "core/analysis/SlipOnsets.h"

namespace rosin::analysis
{

namespace
{
// Least-squares polynomial of degree 1 or 2 through x[begin, end), in a local, scaled time for
// conditioning; evaluate() takes a sample position (fractional allowed).
struct PolynomialFit
{
    double origin = 0.0, scale = 1.0;
    double c[3] = {0.0, 0.0, 0.0};

    double evaluate(double k) const
    {
        const double u = (k - origin) / scale;
        return c[0] + u * (c[1] + u * c[2]);
    }
};

PolynomialFit fitPolynomial(const std::vector<double>& x, std::size_t begin, std::size_t end, int degree)
{
    PolynomialFit fit;
    fit.origin = static_cast<double>(end);
    fit.scale = std::max(1.0, static_cast<double>(end - begin));
    const int m = degree + 1;
    double A[3][3] = {}, b[3] = {};
    for (std::size_t k = begin; k < end; ++k)
    {
        const double u = (static_cast<double>(k) - fit.origin) / fit.scale;
        const double basis[3] = {1.0, u, u * u};
        for (int i = 0; i < m; ++i)
        {
            b[i] += basis[i] * x[k];
            for (int j = 0; j < m; ++j)
                A[i][j] += basis[i] * basis[j];
        }
    }
    // Gaussian elimination with partial pivoting on the small normal equations.
    for (int col = 0; col < m; ++col)
    {
        int pivot = col;
        for (int r = col + 1; r < m; ++r)
            if (std::abs(A[r][col]) > std::abs(A[pivot][col]))
                pivot = r;
        std::swap(A[col], A[pivot]);
        std::swap(b[col], b[pivot]);
        if (A[col][col] == 0.0)
            return fit;
        for (int r = col + 1; r < m; ++r)
        {
            const double f = A[r][col] / A[col][col];
            for (int j = col; j < m; ++j)
                A[r][j] -= f * A[col][j];
            b[r] -= f * b[col];
        }
    }
    for (int i = m - 1; i >= 0; --i)
    {
        double s = b[i];
        for (int j = i + 1; j < m; ++j)
            s -= A[i][j] * fit.c[j];
        fit.c[i] = s / A[i][i];
    }
    return fit;
}

double median(std::vector<double> v)
{
    if (v.empty())
        return 0.0;
    const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    return *mid;
}

struct Prepared
{
    std::vector<double> x;    ///< the force with the sensor's high-pass undone
    std::vector<double> fall; ///< band-limited fall
    std::size_t span = 1;
    double P = 0.0;   ///< nominal period, samples
    double tau = 0.0; ///< bow-to-bridge travel time beta P / 2, samples
};

Prepared prepare(const std::vector<double>& force, const FirstSlipOptions& o)
{
    Prepared p;
    p.x = o.highPassCutoffHz > 0.0 ? undoFirstOrderHighPass(force, o.highPassCutoffHz, o.sampleRate) : force;
    p.span = static_cast<std::size_t>(std::max(1.0, std::round(o.spanSeconds * o.sampleRate)));
    p.fall = bandLimitedFall(p.x, p.span);
    p.P = o.periodSeconds * o.sampleRate;
    p.tau = 0.5 * o.beta * p.P;
    return p;
}

// Everything after the fall has been located: fits, forces, mu_s and the jump. `fitEnd` is one past the
// last sample of the pre-slip rise that may be fitted; `slipPosition` the sample position of the slip.
FirstSlip finish(const Prepared& p, const FirstSlipOptions& o, std::size_t kFall, std::size_t runEnd,
                 std::size_t fitEnd, double slipPosition, std::optional<double> stateForceAtSlip)
{
    FirstSlip r;
    const std::size_t n = p.x.size();
    // The second half of the rise: the start is the string's response to the bow starting, and the sensor
    // high-pass (if not undone) matters least late in the ramp.
    const std::size_t fitBegin = fitEnd / 2;
    const auto afterLength = static_cast<std::size_t>(std::max(8.0, std::round(o.afterWindowPeriods * p.P)));
    const std::size_t afterBegin = std::max(runEnd, kFall + p.span) + 1;
    if (fitEnd < fitBegin + 8 || afterBegin + afterLength > n)
        return r;
    // The step lies between kFall - 1 and kFall.
    const double fallPosition = static_cast<double>(kFall) - 0.5;
    const auto rise = fitPolynomial(p.x, fitBegin, fitEnd, 2);
    const auto after = fitPolynomial(p.x, afterBegin, afterBegin + afterLength, 1);

    r.found = true;
    r.fallTime = fallPosition / o.sampleRate;
    r.firstSlipTime = slipPosition / o.sampleRate;
    r.forceAtSlip = stateForceAtSlip ? *stateForceAtSlip : rise.evaluate(slipPosition);
    r.forceBeforeFall = rise.evaluate(fallPosition);
    r.forceAfterFall = after.evaluate(fallPosition);
    r.muStatic = r.forceAtSlip / ((1.0 - o.beta) * o.bowForce);
    r.jump = (r.forceBeforeFall - r.forceAfterFall) / o.bowForce;
    return r;
}
} // namespace

std::vector<double> undoFirstOrderHighPass(const std::vector<double>& y, double cutoffHz, double sampleRate)
{
    const double g = 2.0 * M_PI * cutoffHz / sampleRate;
    std::vector<double> x(y.size());
    double sum = 0.0;
    for (std::size_t k = 0; k < y.size(); ++k)
    {
        sum += y[k];
        x[k] = y[k] + g * sum;
    }
    return x;
}

FirstSlip firstSlipFromBridgeForce(const std::vector<double>& bridgeForce, const FirstSlipOptions& o)
{
    if (!(o.periodSeconds > 0.0) || !(o.sampleRate > 0.0) || !(o.bowForce > 0.0))
        return {};
    const Prepared p = prepare(bridgeForce, o);
    const std::size_t n = p.x.size(), L = p.span;
    if (n < 8 * L)
        return {};

    // Noise of the band-limited fall from the first 5 ms, which are always before the first slip (the bow
    // starts from rest): a robust (median absolute deviation) rms.
    const std::size_t early =
        std::clamp<std::size_t>(static_cast<std::size_t>(0.005 * o.sampleRate), 4 * L, n / 4);
    std::vector<double> g(p.fall.begin() + static_cast<std::ptrdiff_t>(L),
                          p.fall.begin() + static_cast<std::ptrdiff_t>(std::max(early, L + 1)));
    const double centre = median(g);
    for (double& v : g)
        v = std::abs(v - centre);
    const double noise = 1.4826 * median(g);

    // The first fall that is both well out of the noise and a real share of the force reached.
    double levelSum = 0.0;
    for (std::size_t k = 0; k < L; ++k)
        levelSum += p.x[k];
    auto threshold = [&](double level) { return std::max(o.noiseFactor * noise, o.fallOfLevel * level); };
    for (std::size_t k = L; k + L <= n; ++k)
    {
        const double level = levelSum / static_cast<double>(L); // mean of the L samples before k
        levelSum += p.x[k] - p.x[k - L];
        if (!(level > 0.0) || p.fall[k] <= threshold(level))
            continue;
        // The fall's centre: the peak of the run above threshold.
        std::size_t kFall = k, runEnd = k;
        while (runEnd + L < n && p.fall[runEnd] > threshold(level))
        {
            if (p.fall[runEnd] > p.fall[kFall])
                kFall = runEnd;
            ++runEnd;
        }
        const double fallPosition = static_cast<double>(kFall) - 0.5;
        // The rise up to the slip at the bow, a guard of the derivative span and two samples before it.
        const double fitEnd = fallPosition - p.tau - static_cast<double>(L) - 2.0;
        if (fitEnd < 16.0)
            return {};
        const double slipPosition = o.travelTimeCorrection ? fallPosition - p.tau : fallPosition;
        return finish(p, o, kFall, runEnd, static_cast<std::size_t>(fitEnd), slipPosition, std::nullopt);
    }
    return {};
}

FirstSlip firstSlipFromState(const std::vector<double>& bridgeForce, const std::vector<bool>& sticking,
                             const FirstSlipOptions& o)
{
    if (!(o.periodSeconds > 0.0) || !(o.sampleRate > 0.0) || !(o.bowForce > 0.0))
        return {};
    const auto first = std::find(sticking.begin(), sticking.end(), false);
    const auto kSlip = static_cast<std::size_t>(first - sticking.begin());
    if (kSlip == 0 || kSlip >= bridgeForce.size() || first == sticking.end())
        return {};
    const Prepared p = prepare(bridgeForce, o);
    const std::size_t n = p.x.size(), L = p.span;
    // The fall reaches the bridge about tau after the slip; look a quarter period beyond that.
    const auto searchEnd =
        std::min(n > L ? n - L : 0, kSlip + static_cast<std::size_t>(std::ceil(p.tau + 0.25 * p.P)) + L);
    std::size_t kFall = kSlip;
    for (std::size_t k = kSlip; k < searchEnd; ++k)
        if (p.fall[k] > p.fall[kFall])
            kFall = k;
    std::size_t runEnd = kFall;
    while (runEnd + L < n && p.fall[runEnd] > 0.1 * p.fall[kFall])
        ++runEnd;
    return finish(p, o, kFall, runEnd, kSlip, static_cast<double>(kSlip), p.x[kSlip - 1]);
}

} // namespace rosin::analysis
