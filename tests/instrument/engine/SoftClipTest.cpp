// The output stage's soft clip against its defining properties: identity below the knee, odd, increasing,
// continuous in value and slope at the knee, and never beyond the ceiling for any finite input.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "instrument/engine/SoftClip.h"

namespace rosin::engine
{
namespace ROSIN_FILE_LOCAL
{

TEST(SoftClip, IsTheIdentityBelowTheKnee)
{
    for (double x = -kSoftClipKnee; x <= kSoftClipKnee; x += 0.01)
        EXPECT_EQ(softClip(x), x);
}

TEST(SoftClip, IsOddIncreasingAndBounded)
{
    double previous = softClip(-1e6);
    for (double x = -50.0; x <= 50.0; x += 0.001)
    {
        const double y = softClip(x);
        EXPECT_DOUBLE_EQ(softClip(-x), -y);
        EXPECT_GE(y, previous);
        EXPECT_LE(std::abs(y), kSoftClipCeiling);
        previous = y;
    }
    EXPECT_LE(std::abs(softClip(std::numeric_limits<double>::max())), kSoftClipCeiling);
}

TEST(SoftClip, ValueAndSlopeAreContinuousAtTheKnee)
{
    const double h = 1e-7;
    const double above = softClip(kSoftClipKnee + h);
    EXPECT_NEAR(above, kSoftClipKnee + h, 1e-12); // slope 1 just above the knee (tanh'(0) = 1)
    // The shoulder approaches the ceiling as tanh does: at 2 x (ceiling - knee) above the knee, tanh(2).
    const double room = kSoftClipCeiling - kSoftClipKnee;
    EXPECT_NEAR(softClip(kSoftClipKnee + 2.0 * room), kSoftClipKnee + room * std::tanh(2.0), 1e-15);
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::engine
