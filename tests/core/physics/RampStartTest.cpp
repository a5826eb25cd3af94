// The scaled sticking start (RampStart, used by Guettler scans) against the start it stands in for: a lane of
// the plastic law bowed from rest at N, a, computed sample by sample. Until its first slip the string sticks,
// so its state and friction force must be a times the unit start's, to the modes' float rounding; a trial
// restarted from a skipped start must go on to the same first slip, and nothing may be skipped past the
// point where the friction force reaches 95 % of the sticking limit. The Galluzzo rig's cello D3 on the
// body at beta 0.0899.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "core/physics/lanes/RampStart.h"
#include "core/physics/laws/FrictionLawFactory.h"

using namespace rosin::physics;

namespace ROSIN_FILE_LOCAL
{
constexpr double kRate = 48000.0, kBeta = 0.0899;

class RampStartTest : public ::testing::Test
{
  protected:
    void SetUp() override
    {
        VoiceConfig cfg;
        cfg.string = stringFromCatalogue("cello-D3");
        cfg.body = celloBody();
        voice.prepare(cfg, makeFrictionLaw(FrictionModel::Plastic, galluzzoContact()), kRate);
        voice.setBowPosition(kBeta, 1.0);
        auto make = [] { return makeFrictionLaw(FrictionModel::Plastic, galluzzoContact()); };
        lanes.prepare(voice, makeLaneFriction(make, kRate));
        ramp.prepare(voice, kRate);
    }

    // Lane 0 bowed at N, a from sample `from` (its state already set) to `to`; lane 0's outputs.
    std::vector<VoiceSample> bow(double N, double a, std::size_t from, std::size_t to)
    {
        std::vector<VoiceSample> out;
        LaneBowInput in;
        std::array<VoiceSample, kLanes> s;
        for (std::size_t k = from; k < to; ++k)
        {
            in.bowForce[0] = N;
            in.bowVelocity[0] = a * static_cast<double>(k) / kRate;
            lanes.step(in, s);
            out.push_back(s[0]);
        }
        return out;
    }

    BowedStringVoice voice;
    VoiceLanes lanes;
    RampStart ramp;
};

std::size_t firstSlip(const std::vector<VoiceSample>& s, std::size_t offset = 0)
{
    const auto it = std::find_if(s.begin(), s.end(), [](const VoiceSample& x) { return !x.sticking; });
    return offset + static_cast<std::size_t>(it - s.begin());
}

TEST_F(RampStartTest, StuckStartIsTheUnitStartScaledByTheAcceleration)
{
    const double N = 2.0, a = 0.7;
    const auto fromRest = bow(N, a, 0, 24000);
    const std::size_t slip = firstSlip(fromRest);
    ASSERT_GT(slip, 1000u); // a long sticking rise to compare
    ASSERT_LT(slip, fromRest.size());
    const double limit = *lanes.friction().restingLimit(N);
    const std::size_t skipped = ramp.skippable(a, limit, fromRest.size());
    EXPECT_GT(skipped, slip / 2); // the force grows about as t^2: most of the rise is skipped
    EXPECT_LT(skipped, slip);
    EXPECT_EQ(skipped % RampStart::kStride, 0u);
    double peak = 0.0, worst = 0.0;
    for (std::size_t k = 0; k < skipped; ++k)
    {
        peak = std::max(peak, std::abs(fromRest[k].frictionForce));
        worst = std::max(worst, std::abs(a * ramp.unitSample(k).frictionForce - fromRest[k].frictionForce));
        EXPECT_LE(std::abs(fromRest[k].frictionForce), RampStart::kMargin * limit * (1.0 + 1e-4)) << k;
    }
    EXPECT_LT(worst, 1e-5 * peak);
    // Restarted from the scaled state: the same first slip, the same bridge force to rounding.
    lanes.reset();
    ramp.start(lanes, 0, a, skipped);
    const auto restarted = bow(N, a, skipped, slip + 200);
    EXPECT_EQ(firstSlip(restarted, skipped), slip);
    double gap = 0.0, scale = 0.0;
    for (std::size_t k = skipped; k < slip + 200; ++k)
    {
        gap = std::max(gap, std::abs(restarted[k - skipped].bridgeForce - fromRest[k].bridgeForce));
        scale = std::max(scale, std::abs(fromRest[k].bridgeForce));
    }
    EXPECT_LT(gap, 1e-4 * scale);
    std::printf("[ramp start] N %.1f N, a %.1f m/s^2: first slip at sample %zu, %zu skipped; unit start "
                "scaled agrees to %.1e of the peak friction force, restart to %.1e of the bridge force\n",
                N, a, slip, skipped, worst / peak, gap / scale);
}

TEST_F(RampStartTest, NothingIsSkippedWithoutAnAccelerationOrALimit)
{
    EXPECT_EQ(ramp.skippable(0.0, 1.0, 24000), 0u);
    EXPECT_EQ(ramp.skippable(1.0, 0.0, 24000), 0u);
    EXPECT_EQ(ramp.skippable(1.0, 1.0, 10), 0u); // shorter than one stride
    // A friction curve sticks exactly, up to mu_s N; the viscous law never sticks: no resting limit, so
    // scans never skip its starts.
    auto lanesOf = [this](FrictionModel model)
    {
        auto lanes = std::make_unique<VoiceLanes>();
        lanes->prepare(
            voice, makeLaneFriction([model] { return makeFrictionLaw(model, galluzzoContact()); }, kRate));
        return lanes;
    };
    EXPECT_DOUBLE_EQ(*lanesOf(FrictionModel::Classical)->friction().restingLimit(2.0),
                     2.0 * 1.2); // mu(0) = 1.2
    EXPECT_FALSE(lanesOf(FrictionModel::Viscous)->friction().restingLimit(1.0).has_value());
}

} // namespace ROSIN_FILE_LOCAL
