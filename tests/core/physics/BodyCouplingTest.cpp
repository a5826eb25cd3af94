// The body at the bridge drains energy from the string: partial n of an open string decays faster than on a
// rigid bridge, by the body's loss factor eta_body = 2 Z0 Re Y(f_n) / (pi n) ([Notes §5.1], from the
// reflection coefficient at the bridge), i.e. an extra amplitude decay rate pi f_n eta_body. Partials near
// strong body resonances (large Re Y) decay fastest; a partial in a gap of the admittance hardly changes.
#include <gtest/gtest.h>

#include <cmath>

#include "core/physics/voice/BowedStringVoice.h"
#include "support/Spectrum.h"
#include "support/TestLaws.h"

using namespace rosin;
using namespace rosin::physics;

namespace ROSIN_FILE_LOCAL
{
constexpr double fs = 48000.0;

std::vector<double> pluckResponse(const BodyParameters& body)
{
    VoiceConfig cfg;
    cfg.string = stringFromCatalogue("cello-D3");
    cfg.torsion = false;
    cfg.body = body;
    BowedStringVoice voice;
    voice.prepare(cfg, std::make_unique<test::PrescribedForceLaw>(std::vector<double>{1.0}), fs);
    std::vector<double> x(static_cast<std::size_t>(2.5 * fs));
    for (auto& s : x)
        s = voice.step({0.0, 0.0, 0.0899, 1.0}).bridgeForce;
    return x;
}

/// Amplitude decay rate (1/s) of the partial near f, from two 0.25 s windows 1 s apart.
double decayRate(const std::vector<double>& x, double f)
{
    const std::size_t win = static_cast<std::size_t>(0.25 * fs), nfft = 1 << 16;
    const double bin = fs / nfft;
    const auto a1 = test::findPeak(test::hannSpectrum(x, 0, win, nfft), bin, f - 30.0, f + 30.0);
    const auto a2 = test::findPeak(test::hannSpectrum(x, static_cast<std::size_t>(fs), win, nfft), bin,
                                   f - 30.0, f + 30.0);
    return std::log(a1.magnitude / a2.magnitude);
}

TEST(BodyCoupling, PartialsDecayFasterByTheBodysLossFactor)
{
    const auto body = celloBody();
    const auto rigid = pluckResponse(rigidBody());
    const auto withBody = pluckResponse(body);
    const auto s = stringFromCatalogue("cello-D3");
    double worst = 0.0, largestReY = 0.0, extraAtLargest = 0.0, smallestExtra = 1e9, extraMax = 0.0;
    double smallestPredicted = 1e9, largestPredicted = 0.0;
    for (int n = 2; n <= 12; ++n)
    {
        const double f = n * s.fundamental();
        const double extra = decayRate(withBody, f) - decayRate(rigid, f);
        const double reY = body.admittance(f).real();
        const double predicted = std::numbers::pi * f * 2.0 * s.impedance() * reY / (std::numbers::pi * n);
        EXPECT_GT(extra, 0.0) << "partial " << n;
        worst = std::max(worst, std::abs(extra / predicted - 1.0));
        if (reY > largestReY)
            largestReY = reY, extraAtLargest = extra;
        smallestExtra = std::min(smallestExtra, extra);
        extraMax = std::max(extraMax, extra);
        smallestPredicted = std::min(smallestPredicted, predicted);
        largestPredicted = std::max(largestPredicted, predicted);
    }
    // Partial 1 (146.8 Hz) sits 3 Hz from a body mode (150 Hz) and is pulled and split by it: the
    // perturbation formula is not expected to hold there, so it is left out.
    EXPECT_LT(worst, 0.15);
    EXPECT_EQ(extraAtLargest, extraMax); // strongest admittance, fastest extra decay
    // and the spread between the partials in the body's gaps and on its peaks is the admittance's
    const double spread = extraMax / smallestExtra, predictedSpread = largestPredicted / smallestPredicted;
    EXPECT_GT(predictedSpread, 3.0);
    EXPECT_NEAR(spread / predictedSpread, 1.0, 0.25);
    std::printf(
        "[figure] body-induced decay vs 2 Z0 Re Y/(pi n), partials 2-12: worst error %.1f %%; extra decay "
        "%.3f..%.3f 1/s (predicted spread x%.1f)\n",
        100.0 * worst, smallestExtra, extraMax, predictedSpread);
}

} // namespace ROSIN_FILE_LOCAL
