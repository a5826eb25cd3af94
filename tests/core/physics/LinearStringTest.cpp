// The linear string on a rigid bridge, driven by a force impulse at the bow: mode frequencies against the
// stiff-string formula f_n = n f0 sqrt(1 + B n^2) ([Notes] eq. 4.2), decay rates against the three-term
// loss law ([Notes] eq. 4.1, [Galluzzo2017] Table 1), and torsional modes at n c_t / (2L).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "core/physics/voice/BowedStringVoice.h"
#include "support/Spectrum.h"
#include "support/TestLaws.h"

using namespace rosin;
using namespace rosin::physics;

namespace ROSIN_FILE_LOCAL
{
constexpr double fs = 48000.0;
constexpr double beta = 0.0899; // not a rational with small denominator: every mode n <= 30 is excited

std::vector<double> impulseResponse(const VoiceConfig& cfg, double seconds, bool surface)
{
    BowedStringVoice voice;
    voice.prepare(cfg, std::make_unique<test::PrescribedForceLaw>(std::vector<double>{1.0}), fs);
    std::vector<double> v(static_cast<std::size_t>(seconds * fs));
    for (auto& x : v)
        x = surface ? voice.step({0.0, 0.0, beta, 1.0}).bowPointVelocity
                    : voice.step({0.0, 0.0, beta, 1.0}).bridgeForce;
    return v;
}

VoiceConfig celloD(bool torsion)
{
    VoiceConfig cfg;
    cfg.string = stringFromCatalogue("cello-D3");
    cfg.torsion = torsion;
    return cfg;
}

TEST(LinearString, TransverseModeFrequenciesFollowStiffStringFormula)
{
    const auto cfg = celloD(false);
    const auto v = impulseResponse(cfg, 4.0, true);
    const std::size_t nfft = 1 << 20;
    const auto mag = test::hannSpectrum(v, 0, v.size(), nfft);
    const double bin = fs / nfft;
    const auto& s = cfg.string;
    const double f0 = s.waveSpeed() / (2.0 * s.length);
    const double B = s.inharmonicity(s.length);
    double worst = 0.0;
    for (int n = 1; n <= 30; ++n)
    {
        const double expected = n * f0 * std::sqrt(1.0 + B * n * n);
        const auto peak = test::findPeak(mag, bin, expected - 0.3 * f0, expected + 0.3 * f0);
        const double err = std::abs(test::cents(peak.frequency, expected));
        worst = std::max(worst, err);
        EXPECT_LT(err, 1.0) << "mode " << n << " at " << peak.frequency << " Hz, expected " << expected;
    }
    std::printf("[figure] worst transverse mode error n<=30: %.4f cents\n", worst);
}

TEST(LinearString, ModeDecayRatesFollowLossLaw)
{
    const auto cfg = celloD(false);
    const auto v = impulseResponse(cfg, 4.0, true);
    const auto& s = cfg.string;
    const double f0 = s.waveSpeed() / (2.0 * s.length);
    const double B = s.inharmonicity(s.length);
    const std::size_t win = static_cast<std::size_t>(0.25 * fs), nfft = 1 << 16;
    const double bin = fs / nfft;
    double worst = 0.0;
    for (int n = 1; n <= 30; ++n)
    {
        const double fn = n * f0 * std::sqrt(1.0 + B * n * n);
        const double sigma = 0.5 * s.lossFactor(n, s.length, false) * 2.0 * M_PI * fn; // amplitude decay, 1/s
        const double gap = std::min(3.0, 2.0 / sigma); // about e^-2 between windows
        const std::size_t k2 = static_cast<std::size_t>(gap * fs);
        const auto a1 = test::findPeak(test::hannSpectrum(v, 0, win, nfft), bin, fn - 40, fn + 40);
        const auto a2 = test::findPeak(test::hannSpectrum(v, k2, win, nfft), bin, fn - 40, fn + 40);
        const double measured = std::log(a1.magnitude / a2.magnitude) / (static_cast<double>(k2) / fs);
        const double rel = std::abs(measured / sigma - 1.0);
        worst = std::max(worst, rel);
        EXPECT_LT(rel, 0.05) << "mode " << n << ": sigma " << measured << " expected " << sigma;
    }
    std::printf("[figure] worst decay-rate error n<=30: %.2f %%\n", 100.0 * worst);
}

TEST(LinearString, TorsionalModesAtMultiplesOfHalfTorsionalSpeedOverLength)
{
    // With a prescribed force and a rigid bridge the two wave families do not interact, so the difference
    // between runs with and without torsion is the torsional response alone.
    const auto cfg = celloD(true);
    auto v = impulseResponse(cfg, 2.0, true);
    const auto transverseOnly = impulseResponse(celloD(false), 2.0, true);
    for (std::size_t i = 0; i < v.size(); ++i)
        v[i] -= transverseOnly[i];
    const std::size_t nfft = 1 << 19;
    const auto mag = test::hannSpectrum(v, 0, v.size(), nfft);
    const double bin = fs / nfft;
    const auto& s = cfg.string;
    const double ft = s.torsionalWaveSpeed / (2.0 * s.length);
    double worst = 0.0;
    for (int n = 1; n <= 5; ++n)
    {
        const double expected = n * ft;
        const auto peak = test::findPeak(mag, bin, expected - 0.3 * ft, expected + 0.3 * ft);
        const double err = std::abs(test::cents(peak.frequency, expected));
        worst = std::max(worst, err);
        EXPECT_LT(err, 1.0) << "torsional mode " << n;
    }
    std::printf("[figure] worst torsional mode error n<=5: %.4f cents\n", worst);
}

} // namespace ROSIN_FILE_LOCAL
