// The same gesture rendered at 44.1 kHz and 96 kHz must tell the same physical story: first slip at the same
// time (within 1 %) and the same Helmholtz period (within 0.5 %). Every mode's pole is exact at any rate,
// so the remaining differences come from the junction's time discretisation and the modes kept.
#include <gtest/gtest.h>

#include "core/physics/friction/CurveFrictionLaw.h"
#include "support/Runs.h"

using namespace rosin;
using namespace rosin::physics;

namespace ROSIN_FILE_LOCAL
{
VoiceConfig celloD()
{
    VoiceConfig cfg;
    cfg.string = stringFromCatalogue("cello-D3");
    return cfg;
}

double helmholtzPeriod(double fs)
{
    const auto t =
        test::bowSteady(celloD(), std::make_unique<ClassicalFrictionLaw>(ClassicalCurve{}, "classical"), fs,
                        0.4, 0.05, 0.1, 1.5);
    const auto onsets = test::slipOnsets(t, 1.0);
    return (onsets.back() - onsets.front()) / (onsets.size() - 1);
}

TEST(SampleRateConvergence, FirstSlipTime)
{
    // Guettler's gesture on the Galluzzo rig of [Galluzzo2017]: a = 1.56 m/s^2, 1 N, beta = 0.0899.
    const auto slow =
        test::bowAccelerating(celloD(), std::make_unique<ClassicalFrictionLaw>(ClassicalCurve{}, "c"),
                              44100.0, 1.0, 1.56, 0.0899, 0.2);
    const auto fast =
        test::bowAccelerating(celloD(), std::make_unique<ClassicalFrictionLaw>(ClassicalCurve{}, "c"),
                              96000.0, 1.0, 1.56, 0.0899, 0.2);
    const double t1 = test::firstSlipTime(slow), t2 = test::firstSlipTime(fast);
    ASSERT_GT(t1, 0.0);
    ASSERT_GT(t2, 0.0);
    EXPECT_NEAR(t1 / t2, 1.0, 0.01);
    std::printf("[figure] first slip: %.5f s at 44.1 kHz, %.5f s at 96 kHz (%.3f %%)\n", t1, t2,
                100 * (t1 / t2 - 1));
}

TEST(SampleRateConvergence, HelmholtzPeriod)
{
    const double p1 = helmholtzPeriod(44100.0), p2 = helmholtzPeriod(96000.0);
    EXPECT_NEAR(p1 / p2, 1.0, 0.005);
    std::printf("[figure] Helmholtz period: %.6f s at 44.1 kHz, %.6f s at 96 kHz (%.3f %%)\n", p1, p2,
                100 * (p1 / p2 - 1));
}

} // namespace ROSIN_FILE_LOCAL
