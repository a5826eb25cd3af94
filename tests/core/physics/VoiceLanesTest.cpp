// VoiceLanes (eight trials of one voice in SIMD lanes, used by rosin scan) against the voice it copies: each
// lane must follow its own BowedStringVoice driven with the same bow, to float rounding, and no lane may feel
// another (a scan cell must come out the same whichever cells share its batch). The trial: the Galluzzo rig's
// cello D3 on the cello body at beta 0.0899, bow force 0.5-2.6 N, bow accelerating from rest at 0.5-3 m/s^2
// (Guettler starts), for 50 ms: the sticking rise, the first slips and the first periods of the transient.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>

#include "core/physics/lanes/VoiceLanes.h"
#include "core/physics/laws/FrictionLawFactory.h"

using namespace rosin::physics;

namespace ROSIN_FILE_LOCAL
{
constexpr double kRate = 48000.0, kBeta = 0.0899;
constexpr int kSamples = 2400; // 50 ms

VoiceConfig galluzzoRig(bool bowWithHair)
{
    VoiceConfig cfg;
    cfg.string = stringFromCatalogue("cello-D3");
    cfg.body = celloBody();
    if (bowWithHair)
        cfg.bow = horsehairBow(0.008); // the ribbon and the hair's own state per lane
    return cfg;
}

double force(int lane, int variant)
{
    return 0.5 + 0.3 * ((lane + variant) % kLanes);
}
double acceleration(int lane, int variant)
{
    return 0.5 + 0.35 * ((lane * 3 + variant) % kLanes);
}

// Bridge force of every lane; `variant` changes what lanes other than lane 0 play.
std::vector<std::array<double, kLanes>> runLanes(VoiceLanes& lanes, int variant)
{
    lanes.reset();
    std::vector<std::array<double, kLanes>> out(kSamples);
    LaneBowInput in;
    std::array<VoiceSample, kLanes> s;
    for (int k = 0; k < kSamples; ++k)
    {
        for (int l = 0; l < kLanes; ++l)
        {
            const int v = l == 0 ? 0 : variant;
            in.bowForce[l] = force(l, v);
            in.bowVelocity[l] = acceleration(l, v) * k / kRate;
        }
        lanes.step(in, s);
        for (int l = 0; l < kLanes; ++l)
            out[k][l] = s[l].bridgeForce;
    }
    return out;
}

// A voice at beta 0.0899 and eight lanes copied from it, with the friction law of the test's parameter, bowed
// at a point with rigid hair or by a horsehair ribbon.
class VoiceLanesAgainstVoice : public ::testing::TestWithParam<std::tuple<FrictionModel, bool>>
{
  protected:
    void SetUp() override
    {
        const FrictionModel model = std::get<0>(GetParam());
        const bool bowWithHair = std::get<1>(GetParam());
        voice.prepare(galluzzoRig(bowWithHair), makeFrictionLaw(model, galluzzoContact()), kRate);
        voice.setBowPosition(kBeta, 1.0);
        lanes.prepare(voice,
                      makeLaneFriction([model] { return makeFrictionLaw(model, galluzzoContact()); }, kRate));
    }
    BowedStringVoice voice;
    VoiceLanes lanes;
};

TEST_P(VoiceLanesAgainstVoice, EachLaneFollowsItsOwnVoice)
{
    const auto laneForces = runLanes(lanes, 0);
    double worst = 0.0;
    for (int l = 0; l < kLanes; ++l)
    {
        voice.reset();
        double peak = 0.0, error = 0.0;
        for (int k = 0; k < kSamples; ++k)
        {
            const double F =
                voice.step({force(l, 0), acceleration(l, 0) * k / kRate, kBeta, 1.0}).bridgeForce;
            peak = std::max(peak, std::abs(F));
            error = std::max(error, std::abs(F - laneForces[k][l]));
        }
        worst = std::max(worst, error / peak);
    }
    std::printf("[lanes] %s: largest bridge-force difference from the voice %.2g of the peak\n",
                voice.friction().name(), worst);
    // Float modal sums in another order: measured 8.7e-7 of the peak (classical) and 2.9e-5 (plastic, whose
    // temperature feeds the rounding back); 1e-3 flags a wrong coefficient or a missing term at once.
    EXPECT_LT(worst, 1e-3);
}

TEST_P(VoiceLanesAgainstVoice, LanesDoNotFeelEachOther)
{
    const auto a = runLanes(lanes, 0), b = runLanes(lanes, 3);
    bool othersDiffer = false;
    for (int k = 0; k < kSamples; ++k)
    {
        ASSERT_EQ(a[k][0], b[k][0]) << "sample " << k; // bit for bit
        othersDiffer = othersDiffer || a[k][1] != b[k][1];
    }
    EXPECT_TRUE(othersDiffer);
}

INSTANTIATE_TEST_SUITE_P(Laws, VoiceLanesAgainstVoice,
                         ::testing::Combine(::testing::Values(FrictionModel::Classical,
                                                              FrictionModel::Plastic),
                                            ::testing::Bool()));

} // namespace ROSIN_FILE_LOCAL
