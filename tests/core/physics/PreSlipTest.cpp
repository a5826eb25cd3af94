// Quasi-static pre-slip under a constant-acceleration bow (Guettler's gesture): before the first slip the
// string is dragged with the bow, y = a t^2/2 at the bow, and the bridge force follows the static relation
// f_br = P y / (beta L) ([Woodhouse-thermal] eqs. 3-5). With torsion the string also rolls, so the transverse
// share of the bow-point displacement is Zt ct / (Zt ct + Z0 c). The first slip happens where the friction
// curve says: mu_s = f_br / ((1 - beta) N) = 1.2 (classical) or 0.75 (reconstructed) ([Galluzzo2017] Fig.
// 13).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "core/physics/friction/CurveFrictionLaw.h"
#include "core/physics/voice/BowedStringVoice.h"

using namespace rosin::physics;

namespace ROSIN_FILE_LOCAL
{
struct PreSlipRun
{
    double worstRelativeError = 0.0; ///< |F_br / (P y_expected/(beta L)) - 1| over the checked window
    double muStatic = 0.0;           ///< F_br just before the first slip / ((1-beta) N)
    double firstSlipTime = -1.0;     ///< s
};

// Static compliance at beta of a pinned string with tension and bending stiffness, summed over 10^5 modes
// (independent of the voice's truncated, sampled modes): sum_n 2 sin^2(n pi beta) / (m L omega_n^2).
double stiffStringCompliance(const StringParameters& s, double beta)
{
    double c = 0.0;
    for (int n = 1; n <= 100000; ++n)
    {
        const double k = n * M_PI / s.length;
        c += 2.0 * std::pow(std::sin(n * M_PI * beta), 2) /
             (s.length * (s.tension * k * k + s.bendingStiffness * k * k * k * k));
    }
    return c;
}

PreSlipRun runGuettler(std::unique_ptr<FrictionLaw> law, bool torsion, bool bending = false,
                       double fs = 48000.0)
{
    VoiceConfig cfg;
    cfg.string = stringFromCatalogue("cello-D3");
    cfg.torsion = torsion;
    cfg.bendingStiffness = bending;
    BowedStringVoice voice;
    voice.prepare(cfg, std::move(law), fs);
    const double a = 1.0, N = 1.0, beta = 0.0899;
    const auto& s = cfg.string;
    const double ratio =
        torsion ? s.torsionalImpedance * s.torsionalWaveSpeed /
                      (s.torsionalImpedance * s.torsionalWaveSpeed + s.impedance() * s.waveSpeed())
                : 1.0;
    PreSlipRun run;
    std::vector<double> t, F;
    double lastStuckBridge = 0.0;
    for (int k = 0; k < static_cast<int>(fs); ++k)
    {
        const double time = k / fs;
        const auto out = voice.step({N, a * time, beta, 1.0});
        if (!out.sticking)
        {
            run.firstSlipTime = time;
            break;
        }
        lastStuckBridge = out.bridgeForce;
        t.push_back(time);
        F.push_back(out.bridgeForce);
    }
    run.muStatic = lastStuckBridge / ((1.0 - beta) * N);
    // Check from 20 % of the rise on: the very start is dominated by the string's transient response to the
    // step in bow acceleration (amplitude ~ a / omega_1^2, small against a t^2/2 only after a few periods).
    for (std::size_t i = t.size() / 5; i < t.size(); ++i)
    {
        const double y = ratio * a * t[i] * t[i] / 2.0;
        // Ideal string: f_br = P y / (beta L) ([Woodhouse-thermal] eq. 4). Stiff string: f_br = (1 - beta) y
        // / C_static.
        const double expected =
            bending ? (1.0 - beta) * y / stiffStringCompliance(s, beta) : s.tension * y / (beta * s.length);
        run.worstRelativeError = std::max(run.worstRelativeError, std::abs(F[i] / expected - 1.0));
    }
    return run;
}

TEST(PreSlip, RigidStickingFollowsStaticParabolaWithoutTorsion)
{
    const auto run =
        runGuettler(std::make_unique<ClassicalFrictionLaw>(ClassicalCurve{}, "classical"), false);
    ASSERT_GT(run.firstSlipTime, 0.0);
    EXPECT_LT(run.worstRelativeError, 0.02);
    std::printf("[figure] pre-slip parabola, ideal string, no torsion: worst error %.2f %%\n",
                100 * run.worstRelativeError);
}

// Bending stiffness makes the string about 1.5 % stiffer at the bow than P/(beta (1-beta) L) for the cello D
// at beta = 0.09; the rise then follows the stiff string's own static compliance.
TEST(PreSlip, StiffStringFollowsItsStaticCompliance)
{
    const auto run =
        runGuettler(std::make_unique<ClassicalFrictionLaw>(ClassicalCurve{}, "classical"), false, true);
    ASSERT_GT(run.firstSlipTime, 0.0);
    EXPECT_LT(run.worstRelativeError, 0.02);
    std::printf("[figure] pre-slip parabola, stiff string, no torsion: worst error %.2f %%\n",
                100 * run.worstRelativeError);
}

TEST(PreSlip, TorsionReducesTransverseDisplacementByStiffnessRatio)
{
    const auto run = runGuettler(std::make_unique<ClassicalFrictionLaw>(ClassicalCurve{}, "classical"), true);
    ASSERT_GT(run.firstSlipTime, 0.0);
    EXPECT_LT(run.worstRelativeError, 0.02);
    std::printf("[figure] pre-slip parabola, ideal string with torsion: worst error %.2f %%\n",
                100 * run.worstRelativeError);
}

TEST(PreSlip, FirstSlipAtTheCurvesStaticCoefficient)
{
    const auto classical =
        runGuettler(std::make_unique<ClassicalFrictionLaw>(ClassicalCurve{}, "classical"), true);
    const auto reconstructed =
        runGuettler(std::make_unique<ReconstructedFrictionLaw>(ReconstructedCurve{}, "reconstructed"), true);
    EXPECT_NEAR(classical.muStatic, 1.2, 0.02 * 1.2);
    EXPECT_NEAR(reconstructed.muStatic, 0.75, 0.02 * 0.75);
    // Slip later with the higher static coefficient: the parabola takes longer to reach it.
    EXPECT_GT(classical.firstSlipTime, reconstructed.firstSlipTime);
    std::printf("[figure] first-slip mu_s: classical %.4f (t=%.4f s), reconstructed %.4f (t=%.4f s)\n",
                classical.muStatic, classical.firstSlipTime, reconstructed.muStatic,
                reconstructed.firstSlipTime);
}

} // namespace ROSIN_FILE_LOCAL
