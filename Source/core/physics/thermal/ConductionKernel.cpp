// Disc-average half-space Green's function ([Notes] eq. 2.5) and its non-negative SOE fit (eq. 2.8).
#include "core/physics/thermal/ConductionKernel.h"

#include <compare>
#include <map>
#include <mutex>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <unsupported/Eigen/SpecialFunctions>

namespace rosin::physics
{

namespace
{
/// 1 - e^-u (I0(u) + I1(u)) for u >= 0, using Eigen's exponentially scaled Bessel functions. For small u
/// the difference cancels, so the series u/2 - u^2/4 + 5u^3/48 (from the power series of e^-u, I0, I1)
/// is used instead.
double oneMinusScaledBessel(double u) noexcept
{
    if (u < 1e-4)
        return u * (0.5 - u * (0.25 - u * 5.0 / 48.0));
    return 1.0 - (Eigen::numext::bessel_i0e(u) + Eigen::numext::bessel_i1e(u));
}

/// Lawson-Hanson active-set NNLS: argmin |A x - b| subject to x >= 0. Columns are normalised internally.
/// Off the audio thread only (allocates). Iterations are capped; an index whose unconstrained value is
/// not positive right after it enters the passive set is blocked until x changes (avoids cycling on
/// nearly collinear exponentials).
Eigen::VectorXd nonNegativeLeastSquares(Eigen::MatrixXd A, const Eigen::VectorXd& b)
{
    const Eigen::Index m = A.rows(), n = A.cols();
    Eigen::VectorXd norms = A.colwise().norm().transpose();
    for (Eigen::Index j = 0; j < n; ++j)
        A.col(j) /= (norms[j] > 0.0 ? norms[j] : 1.0);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
    std::vector<bool> passive(static_cast<size_t>(n), false), blocked(static_cast<size_t>(n), false);
    const double tol = 10.0 * std::numeric_limits<double>::epsilon() * static_cast<double>(std::max(m, n));
    const int maxIterations = static_cast<int>(6 * n);
    int iterations = 0;
    while (iterations < maxIterations)
    {
        const Eigen::VectorXd w = A.transpose() * (b - A * x);
        Eigen::Index entering = -1;
        double wMax = tol;
        for (Eigen::Index j = 0; j < n; ++j)
            if (!passive[size_t(j)] && !blocked[size_t(j)] && w[j] > wMax)
                wMax = w[j], entering = j;
        if (entering < 0)
            break;
        passive[size_t(entering)] = true;
        bool first = true;
        while (iterations++ < maxIterations)
        {
            std::vector<Eigen::Index> idx;
            for (Eigen::Index j = 0; j < n; ++j)
                if (passive[size_t(j)])
                    idx.push_back(j);
            Eigen::MatrixXd Ap(m, static_cast<Eigen::Index>(idx.size()));
            for (size_t k = 0; k < idx.size(); ++k)
                Ap.col(Eigen::Index(k)) = A.col(idx[k]);
            const Eigen::VectorXd zp = Ap.colPivHouseholderQr().solve(b);
            Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
            for (size_t k = 0; k < idx.size(); ++k)
                z[idx[k]] = zp[Eigen::Index(k)];
            if (first && z[entering] <= 0.0)
            {
                passive[size_t(entering)] = false; // numerically useless direction: block it for now
                blocked[size_t(entering)] = true;
                break;
            }
            first = false;
            bool feasible = true;
            double alpha = 1.0;
            Eigen::Index leaving = -1;
            for (Eigen::Index j : idx)
                if (z[j] <= 0.0)
                {
                    feasible = false;
                    const double step = x[j] / (x[j] - z[j]);
                    if (leaving < 0 || step < alpha)
                        alpha = step, leaving = j;
                }
            if (feasible)
            {
                x = z;
                std::fill(blocked.begin(), blocked.end(), false);
                break;
            }
            x += alpha * (z - x);
            x[leaving] = 0.0; // exactly on the boundary
            for (Eigen::Index j : idx)
                if (x[j] <= 0.0)
                    x[j] = 0.0, passive[size_t(j)] = false;
            std::fill(blocked.begin(), blocked.end(), false);
        }
    }
    for (Eigen::Index j = 0; j < n; ++j)
        x[j] /= (norms[j] > 0.0 ? norms[j] : 1.0);
    return x;
}
} // namespace

double ConductionKernel::green(double t, double a, double K, double rhoC) noexcept
{
    if (!(t > 0.0))
        return 0.0;
    const double kappa = K / rhoC;
    const double u = a * a / (2.0 * kappa * t);
    const double oneD = 1.0 / (std::numbers::pi * a * a * rhoC * std::sqrt(std::numbers::pi * kappa * t));
    return oneD * oneMinusScaledBessel(u);
}

double ConductionKernel::steadyResistance(double a, double K) noexcept
{
    return 8.0 / (3.0 * std::numbers::pi * std::numbers::pi * K * a);
}

double ConductionKernel::integrateGreen(double t0, double t1, double a, double K, double rhoC, int n) noexcept
{
    // t = s^2, dt = 2 s ds; near s = 0, G(s^2) 2 s -> 2 / (A e sqrt(pi)), finite and smooth.
    n += n % 2;
    const double s0 = std::sqrt(std::max(t0, 0.0)), s1 = std::sqrt(t1), h = (s1 - s0) / n;
    auto f = [&](double s)
    {
        if (s <= 0.0) // limit of G(s^2) 2 s at s = 0: 2 / (pi a^2 rho c sqrt(pi kappa))
            return 2.0 / (std::numbers::pi * a * a * rhoC * std::sqrt(std::numbers::pi * K / rhoC));
        return green(s * s, a, K, rhoC) * 2.0 * s;
    };
    double sum = f(s0) + f(s1);
    for (int i = 1; i < n; ++i)
        sum += f(s0 + i * h) * (i % 2 ? 4.0 : 2.0);
    return sum * h / 3.0;
}

namespace
{
// Fits already made in this process, by their inputs: a scan or rosin discover prepares the same contact
// thousands of times (every trial simulator of every fit), and the NNLS fit cost a tenth of their time.
// prepare() runs off the audio thread, so a lock here is allowed; the cache is dropped when it grows large.
struct FitKey
{
    double a, K, rhoC, dt, maxTime, tauBelowDt, tauAboveMax, integralWeight, maxRelativeError;
    int terms, minimumTerms, startTerms, maximumTerms, pointsPerDecade;
    auto operator<=>(const FitKey&) const = default;
};
struct FitResult
{
    double g0;
    std::vector<double> tau, c;
};
constexpr std::size_t kMaxCachedFits = 512;
std::mutex fitCacheMutex;
std::map<FitKey, FitResult>& fitCache()
{
    static std::map<FitKey, FitResult> cache;
    return cache;
}
} // namespace

void ConductionKernel::fit(double a, double K, double rhoC, double dt, const FitOptions& opt)
{
    radius_ = a, conductivity_ = K, heatCapacity_ = rhoC, dt_ = dt;
    const FitKey key{a,
                     K,
                     rhoC,
                     dt,
                     opt.maxTime,
                     opt.tauBelowDt,
                     opt.tauAboveMax,
                     opt.integralWeight,
                     opt.maxRelativeError,
                     opt.terms,
                     opt.minimumTerms,
                     opt.startTerms,
                     opt.maximumTerms,
                     opt.pointsPerDecade};
    {
        std::lock_guard<std::mutex> lock(fitCacheMutex);
        if (const auto it = fitCache().find(key); it != fitCache().end())
        {
            g0_ = it->second.g0, tau_ = it->second.tau, c_ = it->second.c;
            return;
        }
    }
    fitUncached(a, K, rhoC, dt, opt);
    std::lock_guard<std::mutex> lock(fitCacheMutex);
    if (fitCache().size() >= kMaxCachedFits)
        fitCache().clear();
    fitCache()[key] = {g0_, tau_, c_};
}

void ConductionKernel::fitUncached(double a, double K, double rhoC, double dt, const FitOptions& opt)
{
    g0_ = integrateGreen(0.0, dt, a, K, rhoC);
    if (opt.terms > 0)
        return fitTerms(a, K, rhoC, dt, opt, opt.terms);
    // The fewest terms that keep the accuracy: every term costs two multiply-adds per sample and solid on the
    // audio thread, so the fit, which runs once per contact, does the searching. It starts where audio rates
    // and contact sizes end up (20-26) and walks down while the accuracy holds, else up until it does.
    auto meets = [&](int M)
    {
        fitTerms(a, K, rhoC, dt, opt, M);
        return maxRelativeError(dt, opt.maxTime) <= opt.maxRelativeError;
    };
    const int lowest = std::max(opt.minimumTerms, 2);
    int M = std::clamp(opt.startTerms, lowest, opt.maximumTerms);
    if (meets(M))
    {
        while (M > lowest && meets(M - 1))
            --M;
        fitTerms(a, K, rhoC, dt, opt, M); // the last fit tried may have missed
        return;
    }
    while (M < opt.maximumTerms && !meets(++M))
        ;
}

void ConductionKernel::fitTerms(double a, double K, double rhoC, double dt, const FitOptions& opt, int terms)
{
    const int M = std::max(terms, 2);
    const double tauLo = std::log(opt.tauBelowDt * dt), tauHi = std::log(opt.tauAboveMax * opt.maxTime);
    tau_.resize(size_t(M));
    for (int k = 0; k < M; ++k)
        tau_[size_t(k)] = std::exp(tauLo + (tauHi - tauLo) * k / (M - 1));

    const double decades = std::log10(opt.maxTime / dt);
    const int points = std::max(static_cast<int>(std::ceil(decades * opt.pointsPerDecade)) + 1, 2 * M);
    Eigen::MatrixXd A(points + 1, M);
    Eigen::VectorXd b = Eigen::VectorXd::Ones(points + 1);
    for (int i = 0; i < points; ++i)
    {
        const double t = dt * std::pow(opt.maxTime / dt, double(i) / (points - 1));
        const double g = green(t, a, K, rhoC);
        for (int k = 0; k < M; ++k)
            A(i, k) = std::exp(-t / tau_[size_t(k)]) / g; // relative error
    }
    // Steady-resistance row: sum c tau e^{-dt/tau} = int_dt^inf G (the scheme's steady state, see header).
    const double tail = steadyResistance(a, K) - g0_;
    for (int k = 0; k < M; ++k)
        A(points, k) = opt.integralWeight * tau_[size_t(k)] * std::exp(-dt / tau_[size_t(k)]) / tail;
    b[points] = opt.integralWeight;

    const Eigen::VectorXd c = nonNegativeLeastSquares(A, b);
    c_.clear();
    std::vector<double> usedTau;
    for (int k = 0; k < M; ++k)
        if (c[k] > 0.0) // NNLS leaves some exactly at zero: a term that would only cost time
            c_.push_back(c[k]), usedTau.push_back(tau_[size_t(k)]);
    tau_ = std::move(usedTau);
}

double ConductionKernel::evaluate(double t) const noexcept
{
    double s = 0.0;
    for (size_t k = 0; k < c_.size(); ++k)
        s += c_[k] * std::exp(-t / tau_[k]);
    return s;
}

double ConductionKernel::integral() const noexcept
{
    double s = 0.0;
    for (size_t k = 0; k < c_.size(); ++k)
        s += c_[k] * tau_[k];
    return s;
}

double ConductionKernel::washedOutResistance(double a, double K, double rhoC, double washoutTime) noexcept
{
    if (!(washoutTime > 0.0) || !std::isfinite(washoutTime))
        return steadyResistance(a, K);
    // t G(t) e^{-t/tau} is smooth in x = ln t: near 0 it goes as sqrt(t), past tau it dies exponentially.
    const double x0 = std::log(1e-9 * std::min(washoutTime, a * a * rhoC / K));
    const double x1 = std::log(60.0 * washoutTime);
    const int n = 2 * static_cast<int>(std::ceil(40.0 * (x1 - x0))); // even, ~80 points per e-fold
    const double h = (x1 - x0) / n;
    auto f = [&](double x)
    {
        const double t = std::exp(x);
        return t * green(t, a, K, rhoC) * std::exp(-t / washoutTime);
    };
    double sum = f(x0) + f(x1);
    for (int i = 1; i < n; ++i)
        sum += (i % 2 ? 4.0 : 2.0) * f(x0 + i * h);
    // Below t0 = e^x0 the 1-D limit G = 1 / (A e sqrt(pi t)) integrates to 2 sqrt(t0) / (A e sqrt(pi)).
    const double t0 = std::exp(x0);
    const double below =
        2.0 * std::sqrt(t0) / (std::numbers::pi * a * a * std::sqrt(K * rhoC * std::numbers::pi));
    return sum * h / 3.0 + below;
}

double ConductionKernel::discreteSteadyResistance() const noexcept
{
    double s = g0_;
    for (size_t k = 0; k < c_.size(); ++k)
        s += c_[k] * tau_[k] * std::exp(-dt_ / tau_[k]);
    return s;
}

double ConductionKernel::maxRelativeError(double t0, double t1) const noexcept
{
    const int n = std::max(2, static_cast<int>(100.0 * std::log10(t1 / t0)) + 1);
    double worst = 0.0;
    for (int i = 0; i < n; ++i)
    {
        const double t = t0 * std::pow(t1 / t0, double(i) / (n - 1));
        const double g = green(t, radius_, conductivity_, heatCapacity_);
        worst = std::max(worst, std::abs(evaluate(t) / g - 1.0));
    }
    return worst;
}

} // namespace rosin::physics
