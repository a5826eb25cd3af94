// The signature rule of rosin discover (admitBySignature, EffectSearch.h): which candidates the paired test
// left short it makes significant. Each of its three conditions must hold, a candidate already significant
// keeps its paired-test standing, and a fit at its null is never admitted, however its signature scores.
#include <gtest/gtest.h>

#include "lab/discovery/discover/EffectSearch.h"

using namespace rosin::discovery;

namespace ROSIN_FILE_LOCAL
{
/// A candidate the paired test left short by a little: every signature condition met with margin.
EffectScore shortOfAlpha()
{
    EffectScore s;
    s.leftNull = true;
    s.heldOutGain = 1.5 * kSignatureMinGain;
    s.pValue = 0.5 * kSignatureScreenP;
    s.signature.z = 1.5 * kSignatureZ;
    return s;
}

TEST(SignatureRule, AdmitsACandidateMeetingAllThree)
{
    EffectScore s = shortOfAlpha();
    admitBySignature(s);
    EXPECT_TRUE(s.significant);
    EXPECT_TRUE(s.bySignature);
}

TEST(SignatureRule, EachConditionIsNeeded)
{
    EffectScore weak = shortOfAlpha(), worse = shortOfAlpha(), loose = shortOfAlpha();
    weak.signature.z = 0.5 * kSignatureZ;
    worse.heldOutGain = -0.4; // a signature following the residual's structure, the fit worse for it
    loose.pValue = 2.0 * kSignatureScreenP;
    for (EffectScore* s : {&weak, &worse, &loose})
    {
        admitBySignature(*s);
        EXPECT_FALSE(s->significant);
        EXPECT_FALSE(s->bySignature);
    }
}

TEST(SignatureRule, LeavesAFitAtItsNullAndAPairedTestVerdictAlone)
{
    EffectScore null = shortOfAlpha();
    null.leftNull = false;
    admitBySignature(null);
    EXPECT_FALSE(null.significant);

    EffectScore named = shortOfAlpha();
    named.significant = true; // by the paired test
    admitBySignature(named);
    EXPECT_TRUE(named.significant);
    EXPECT_FALSE(named.bySignature);
}

} // namespace ROSIN_FILE_LOCAL
