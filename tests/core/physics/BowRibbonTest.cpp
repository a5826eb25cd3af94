// The bow's width and hair (BowRibbon.h, BowHair.h), each against an expectation of its own:
//  - compliant hair: before the first slip the hair and the string are two springs in series, so the
//    stretched hair takes a share k_s / (k_h + k_s) of the bow's travel and the bridge force of the static
//    pre-slip rise ([Woodhouse-thermal] eqs. 3-5) falls by the factor k_h / (k_h + k_s), k_s = P / (beta (1 -
//    beta) L) the ideal string's stiffness at the bow, less a little more while the hair's dashpot lags;
//  - the hair alone: its trapezoidal step has the admittance i w / (k_h + i w r_h) of a spring and dashpot in
//    parallel, exactly at the bilinear map's warped frequency and within 1 % of the continuous one at 1 kHz;
//  - (tests/core/analysis/BowBrightnessTest.cpp: the mode that averages out over the ribbon is not bowed);
//  - the ribbon-mean instantaneous admittance of the modes alone approaches the continuous string's
//    triangle response (BowRibbon.h) as the ribbon widens: a second method for the band correction's target.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>
#include <vector>

#include "core/physics/bow/BowHair.h"
#include "core/physics/bow/BowParameters.h"
#include "core/physics/bow/BowRibbon.h"
#include "core/physics/friction/CurveFrictionLaw.h"
#include "core/physics/laws/FrictionLawFactory.h"
#include "support/Runs.h"

using namespace rosin;
using namespace rosin::physics;

namespace ROSIN_FILE_LOCAL
{
constexpr double kFs = 48000.0, kBeta = 0.0899;

VoiceConfig idealString(const BowParameters& bow)
{
    VoiceConfig cfg;
    cfg.string = stringFromCatalogue("cello-D3");
    cfg.torsion = false;
    cfg.bendingStiffness = false;
    cfg.bow = bow;
    return cfg;
}

/// Bridge force before the first slip under a constant-acceleration bow (a = 1 m/s^2, N = 1 N).
std::vector<double> preSlipBridgeForce(const BowParameters& bow)
{
    BowedStringVoice voice;
    voice.prepare(idealString(bow), std::make_unique<ClassicalFrictionLaw>(ClassicalCurve{}, "classical"),
                  kFs);
    std::vector<double> F;
    for (int k = 0; k < static_cast<int>(kFs); ++k)
    {
        const auto out = voice.step({1.0, k / kFs, kBeta, 1.0});
        if (!out.sticking)
            break;
        F.push_back(out.bridgeForce);
    }
    return F;
}

double worstSeriesSpringError(const BowParameters& hair)
{
    const auto rigid = preSlipBridgeForce({});
    const auto compliant = preSlipBridgeForce(hair);
    const auto s = stringFromCatalogue("cello-D3");
    const double ks = s.tension / (kBeta * (1.0 - kBeta) * s.length);
    // Quasi-static chain: f = k_s y = -(k_h x + r_h x'), y = y_b + x, y_b = a t^2 / 2 (a = 1). The hair's
    // stretch x = A t^2 + B t + C once its dashpot's transient, exp(-(k_s + k_h) t / r_h), has gone.
    const double k = hair.hairStiffness, r = hair.hairDamping, K = ks + k;
    const double A = -ks / (2.0 * K), B = -2.0 * r * A / K, C = -r * B / K;
    const auto expected = [&](double t) { return 1.0 + (A * t * t + B * t + C) / (0.5 * t * t); };
    // The softer chain slips later; compare while both stick, from 20 % of the rise (PreSlipTest: the start
    // is the string's transient answer to the step in acceleration).
    const std::size_t n = std::min(rigid.size(), compliant.size());
    EXPECT_GT(n, 1000u);
    double worst = 0.0;
    for (std::size_t i = n / 5; i < n; ++i)
        worst = std::max(worst, std::abs(compliant[i] / rigid[i] / expected(i / kFs) - 1.0));
    std::printf(
        "[figure] hair k_h %.3g N/m, r_h %.3g kg/s against the string's k_s %.3g N/m: pre-slip bridge "
        "force x %.4f (springs alone: %.4f) at the last stuck sample, worst deviation %.2f %%\n",
        k, r, ks, expected((n - 1) / kFs), k / K, 100.0 * worst);
    return worst;
}

TEST(BowHair, HairAndStringAreSpringsInSeriesBeforeTheFirstSlip)
{
    EXPECT_LT(worstSeriesSpringError(horsehairBow(0.0)), 0.01); // the handbook hair: 5 % softer chain
    BowParameters soft = horsehairBow(0.0);
    soft.hairStiffness = 5000.0; // a soft hair: 28 % of the travel in the hair, its dashpot 6 % more
    EXPECT_LT(worstSeriesSpringError(soft), 0.01);
}

TEST(BowHair, TrapezoidalHairIsASpringAndDashpotInParallel)
{
    const BowParameters bow = horsehairBow(0.0);
    const HairTerms t = hairTerms(bow, kFs);
    const double f = 1000.0, w = 2.0 * std::numbers::pi * f;
    HairState s;
    std::complex<double> force{}, velocity{};
    const int periods = 400, perPeriod = static_cast<int>(kFs / f * periods);
    for (int k = 0; k < 2 * perPeriod; ++k)
    {
        const double fk = std::sin(w * k / kFs);
        const double xd = advanceHair(t, s, hairHistory(t, s), fk);
        if (k >= perPeriod) // steady state: the dashpot's time constant r/k is 0.14 ms
        {
            const auto e = std::polar(1.0, -w * k / kFs);
            force += fk * e;
            velocity += xd * e;
        }
    }
    // x' answers the hair's force -f: Y(w) = x' / (-f).
    const std::complex<double> measured = -velocity / force;
    const auto admittance = [&](double omega)
    {
        const std::complex<double> iw(0.0, omega);
        return iw / (bow.hairStiffness + iw * bow.hairDamping);
    };
    const double warped = 2.0 * kFs * std::tan(w / (2.0 * kFs));
    EXPECT_LT(std::abs(measured / admittance(warped) - 1.0), 1e-6);
    EXPECT_LT(std::abs(measured / admittance(w) - 1.0), 0.01);
    std::printf("[figure] hair admittance at 1 kHz: |Y| %.4g s/kg, continuous %.4g, warped %.4g\n",
                std::abs(measured), std::abs(admittance(w)), std::abs(admittance(warped)));
}

TEST(BowRibbon, ModalAdmittanceOverTheRibbonMeetsTheContinuousString)
{
    // The modes alone, without the band correction: their ribbon-mean direct term against (2u - u^2) / (2
    // Z0). A point's modal answer falls short (the modes stop at 0.45 fs), a ribbon wider than c T / 2 has
    // its high modes averaged away, so the truncation costs little.
    const auto s = stringFromCatalogue("cello-D3");
    const double cT = s.waveSpeed() / kFs;
    for (double width : {2.0 * cT, 6.0 * cT})
    {
        BowedStringVoice voice;
        voice.prepare(idealString({.width = width}),
                      makeFrictionLaw(FrictionModel::Classical, galluzzoContact()), kFs);
        voice.setBowPosition(kBeta, 1.0);
        const double continuous = ribbonDirectShare(s.waveSpeed(), 1.0 / kFs, width) / (2.0 * s.impedance());
        const JunctionTerms& j = voice.coefficients().junction;
        const double modal = j.y0 - j.bandCorrection;
        std::printf("[figure] ribbon %.1f mm (%.0f c T): modal y0 %.4g s/kg, continuous string %.4g\n",
                    1e3 * width, width / cT, modal, continuous);
        EXPECT_NEAR(modal / continuous, 1.0, 0.1);
    }
}

} // namespace ROSIN_FILE_LOCAL
