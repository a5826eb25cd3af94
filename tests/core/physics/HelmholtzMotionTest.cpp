// Steady bowing inside Schelleng's limits settles into Helmholtz motion: one slip per period, period 1/f0,
// slip for a fraction beta of the period ([Notes §6.1], eq. 6.1; euphonics 9.3.1).
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "core/physics/friction/CurveFrictionLaw.h"
#include "core/physics/laws/FrictionLawFactory.h"
#include "support/Runs.h"

using namespace rosin;
using namespace rosin::physics;

namespace ROSIN_FILE_LOCAL
{
struct HelmholtzFigures
{
    double period = 0.0;        ///< mean interval between flyback onsets, s
    double slipFraction = 0.0;  ///< share of time the string moves backwards (the flyback of the sawtooth)
    int maxSlipsPerPeriod = 0;  ///< most flyback onsets in any nominal period window
    int minSlipsPerPeriod = 99; ///< fewest
    int partialSlips = 0;       ///< sliding episodes in which the string only lagged the bow
};

// Slips are counted as flybacks, episodes in which the string moves backwards (test::SlipEpisode): the
// events that make the Helmholtz sawtooth and that a bridge-force analysis sees. Partial slips, where the
// string briefly lags the bow and goes on forwards, are counted and reported but do not break the regime.
HelmholtzFigures analyse(const test::Trace& t, double f0, double fromSeconds)
{
    HelmholtzFigures h;
    std::vector<double> onsets;
    double slipping = 0.0;
    for (const auto& e : test::slipEpisodes(t, fromSeconds))
    {
        if (!e.flyback())
        {
            ++h.partialSlips;
            continue;
        }
        onsets.push_back(e.start);
        slipping += e.backwardDuration;
    }
    if (onsets.size() < 3)
        return h;
    h.period = (onsets.back() - onsets.front()) / (onsets.size() - 1);
    h.slipFraction = slipping / (onsets.back() - onsets.front() + h.period);
    // Count onsets in consecutive windows of one nominal period starting half a period before each onset.
    const double P = 1.0 / f0;
    for (double w = onsets.front() - 0.5 * P; w + P < onsets.back(); w += P)
    {
        const int n = static_cast<int>(
            std::count_if(onsets.begin(), onsets.end(), [&](double x) { return x >= w && x < w + P; }));
        h.maxSlipsPerPeriod = std::max(h.maxSlipsPerPeriod, n);
        h.minSlipsPerPeriod = std::min(h.minSlipsPerPeriod, n);
    }
    return h;
}

/// Slip fraction / beta allowed: the ideal Helmholtz motion's 1, widened by how much the law rounds the
/// corner.
struct SlipBand
{
    double low = 0.75, high = 1.25;
};

void expectHelmholtzWith(const VoiceConfig& cfg, std::unique_ptr<FrictionLaw> law, const char* name,
                         double force, double beta, SlipBand band = {})
{
    const double speed = 0.05;
    const auto t = test::bowSteady(cfg, std::move(law), 48000.0, force, speed, beta, 1.5);
    const double f0 = cfg.string.fundamental();
    const auto h = analyse(t, f0, 1.0);
    EXPECT_EQ(h.maxSlipsPerPeriod, 1) << name;
    EXPECT_EQ(h.minSlipsPerPeriod, 1) << name;
    EXPECT_NEAR(h.period * f0, 1.0, 0.01) << name;
    EXPECT_GE(h.slipFraction / beta, band.low) << name;
    EXPECT_LE(h.slipFraction / beta, band.high) << name;
    std::printf("[figure] Helmholtz %s F=%.2f N: period error %.3f %%, slip fraction %.4f (beta %.4f), "
                "%d partial slips in 0.5 s\n",
                name, force, 100.0 * (h.period * f0 - 1.0), h.slipFraction, beta, h.partialSlips);
}
template <typename Law, typename Curve>
void expectHelmholtz(Curve curve, const char* name, double force, double beta, bool body)
{
    VoiceConfig cfg;
    cfg.string = stringFromCatalogue("cello-D3");
    if (body)
        cfg.body = celloBody();
    expectHelmholtzWith(cfg, std::make_unique<Law>(curve, name), name, force, beta);
}

// The cello D string with the cello body, bowed at 0.05 m/s and beta = 0.1 ([Galluzzo2017]'s Schelleng grid
// speed). Schelleng's maximum force 2 Z0 vb / (beta (mu_s - mu_d)) is 0.64 N for the classical curve and 1.37
// N for the reconstructed one ([Notes §6.1]). Near the limits the string is bistable (Helmholtz or double
// slipping, decided by the start: [Galluzzo2017] calls such sensitive dependence genuine); each force below
// sits inside the region that a scan over 0.2-2 N found for its law.
TEST(HelmholtzMotion, ClassicalCurve)
{
    expectHelmholtz<ClassicalFrictionLaw>(ClassicalCurve{}, "classical", 0.3, 0.1, true);
}

TEST(HelmholtzMotion, ReconstructedCurve)
{
    expectHelmholtz<ReconstructedFrictionLaw>(ReconstructedCurve{}, "reconstructed", 0.3, 0.1, true);
}

// The plastic law leaves partial slips, in which the string lags the bow without reversing; they are
// reported. Its flybacks are rounded: each starts into a contact cooled to ~7 K while stuck (both solids
// conduct), whose friction (mu ~0.6) only falls as the slip heats it, and ends as it cools again; measured
// over this law's Helmholtz window at beta 0.1, v_b 0.05 m/s (0.12-0.42 N): slip fraction 1.30-1.39 beta
// (0.15-0.4 N), so the band is 1.0-1.5 beta. 0.25 N is the window's middle. (With the old one-sided balance,
// at 50-65 K, the window reached 0.5 N and the slip was within 25 % of beta.)
TEST(HelmholtzMotion, PlasticThermalLaw)
{
    VoiceConfig cfg;
    cfg.string = stringFromCatalogue("cello-D3");
    cfg.body = celloBody();
    expectHelmholtzWith(cfg, makeFrictionLaw(FrictionModel::Plastic, galluzzoContact()), "plastic", 0.25, 0.1,
                        {1.0, 1.5});
}

} // namespace ROSIN_FILE_LOCAL
