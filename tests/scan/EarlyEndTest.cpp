// A Guettler trial that ends once its transient is decided (ScanSpec::endAfterTransient) must report the
// same first slip and the same transient as the whole 0.5 s trial: the analysis reads only the first 2 x cap
// periods after the first full flyback, and the samples before the end are the same computation. Checked
// cell by cell against whole trials, for a friction curve and a thermal law, over the seed's force and
// acceleration ranges at beta 0.0899. The first slip is identical. The transient is counted in the period
// measured at the end of the trial when that is Helmholtz motion (CellAnalysis.h), which the early end
// measures a little sooner: reached or not must agree, the length within 0.1 % (measured: 0.01 %). The
// regime (of the last 20 periods) may differ, since it is then taken earlier: the agreement is printed.
#include <gtest/gtest.h>

#include <cstdio>

#include "lab/scan/Axis.h"
#include "lab/scan/CellRunner.h"

using namespace rosin::scan;

namespace
{
ScanSpec grid(const char* law, bool early)
{
    ScanSpec s = defaultSpec(ScanKind::Guettler);
    s.model.friction = law;
    s.betas = {0.0899};
    s.forces = linearAxis(0.4, 3.2, 5);
    s.second = linearAxis(0.08, 3.2, 5);
    s.endAfterTransient = early;
    return s;
}

class EarlyEnd : public ::testing::TestWithParam<const char*>
{
};
} // namespace

TEST_P(EarlyEnd, SameFirstSlipAndTransientAsWholeTrials)
{
    const ScanSpec earlySpec = grid(GetParam(), true), wholeSpec = grid(GetParam(), false);
    CellRunner early(earlySpec), whole(wholeSpec);
    std::size_t earlySamples = 0, wholeSamples = 0, sameRegime = 0, ended = 0;
    const std::size_t cells = earlySpec.cellCount();
    for (std::size_t c = 0; c < cells; ++c)
    {
        const CellResult a = early.run(c), b = whole.run(c);
        earlySamples += early.lastSamples().size();
        wholeSamples += whole.lastSamples().size();
        ended += early.lastSamples().size() < whole.lastSamples().size() ? 1 : 0;
        sameRegime += a.regime == b.regime ? 1 : 0;
        SCOPED_TRACE("cell " + std::to_string(c));
        EXPECT_EQ(a.muStatic, b.muStatic);
        EXPECT_EQ(a.jump, b.jump);
        EXPECT_EQ(a.firstSlipTime, b.firstSlipTime);
        ASSERT_EQ(a.transientPeriods.has_value(), b.transientPeriods.has_value());
        if (a.transientPeriods)
            EXPECT_NEAR(*a.transientPeriods, *b.transientPeriods, 1e-3 * *b.transientPeriods);
        EXPECT_EQ(a.failure, b.failure);
    }
    std::printf("[early end] %s: %zu of %zu trials ended early, %.1f %% of the samples, same regime in %zu\n",
                GetParam(), ended, cells, 100.0 * earlySamples / wholeSamples, sameRegime);
    // Measured: 23 (classical) and 24 (plastic) of 25; the rest flyback too late to end before 0.5 s.
    EXPECT_GT(ended, cells / 2);
}

INSTANTIATE_TEST_SUITE_P(Laws, EarlyEnd, ::testing::Values("classical", "plastic"));
