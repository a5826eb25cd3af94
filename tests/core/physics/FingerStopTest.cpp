// A finger stop shortens the vibrating length to r L and, as [Galluzzo2017] Table 1 says for the
// finger-stopped string, raises eta_F from 23 to 69 (x 1e-5): partials sit at n f0/r sqrt(1 + B n^2 / r^2)
// and decay at the stopped loss law's rate.
#include <gtest/gtest.h>

#include <cmath>

#include "core/physics/voice/BowedStringVoice.h"
#include "support/Spectrum.h"
#include "support/TestLaws.h"

using namespace rosin;
using namespace rosin::physics;

TEST(FingerStop, ShorterStringWithStoppedDamping)
{
    constexpr double fs = 48000.0, ratio = 2.0 / 3.0; // a fifth above the open string
    VoiceConfig cfg;
    cfg.string = stringFromCatalogue("cello-D3");
    cfg.torsion = false;
    BowedStringVoice voice;
    voice.prepare(cfg, std::make_unique<test::PrescribedForceLaw>(std::vector<double>{1.0}), fs);
    std::vector<double> x(static_cast<std::size_t>(3.0 * fs));
    for (auto& s : x)
        s = voice.step({0.0, 0.0, 0.0899, ratio}).bowPointVelocity;

    const auto& s = cfg.string;
    const double L = ratio * s.length;
    const double f0 = s.waveSpeed() / (2.0 * L), B = s.inharmonicity(L);
    const auto mag = test::hannSpectrum(x, 0, x.size(), 1 << 20);
    const double bin = fs / (1 << 20);
    const std::size_t win = static_cast<std::size_t>(0.25 * fs), nfft = 1 << 16;
    double worstCents = 0.0, worstDecay = 0.0;
    for (int n = 1; n <= 6; ++n)
    {
        const double fn = n * f0 * std::sqrt(1.0 + B * n * n);
        const auto peak = test::findPeak(mag, bin, fn - 0.3 * f0, fn + 0.3 * f0);
        worstCents = std::max(worstCents, std::abs(test::cents(peak.frequency, fn)));
        const double sigma = 0.5 * s.lossFactor(n, L, true) * 2.0 * M_PI * fn;
        const double gap = std::min(2.0, 2.0 / sigma);
        const auto k2 = static_cast<std::size_t>(gap * fs);
        const double measured =
            std::log(
                test::findPeak(test::hannSpectrum(x, 0, win, nfft), fs / nfft, fn - 40, fn + 40).magnitude /
                test::findPeak(test::hannSpectrum(x, k2, win, nfft), fs / nfft, fn - 40, fn + 40).magnitude) /
            (static_cast<double>(k2) / fs);
        worstDecay = std::max(worstDecay, std::abs(measured / sigma - 1.0));
        // The open-string law would be clearly slower: the stopped damping is really applied.
        EXPECT_GT(measured, 1.5 * 0.5 * s.lossFactor(n, L, false) * 2.0 * M_PI * fn) << n;
    }
    EXPECT_LT(worstCents, 1.0);
    EXPECT_LT(worstDecay, 0.05);
    std::printf("[figure] finger stop at 2/3: worst partial error %.4f cents, worst decay error %.2f %%\n",
                worstCents, 100.0 * worstDecay);
}
