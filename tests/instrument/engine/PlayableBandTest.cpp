// Each string's playable band as the engine builds it (engine::playableBand): Schelleng's limits from the
// string's Z0, its losses as a bridge conductance and the friction law's mu_s, mu_d ([Notes §6]). Checked
// against the formulas written out from the strings' tension and density, and for what the musical mapping
// needs of it: along the whole dynamics path, on every string of either instrument, the band is open
// (F_min < F_max, with the lab's corrections of both edges) and the placed force lies inside it from mf
// on (towards pp it stops at the force floor) at the normal placement.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "instrument/engine/Engine.h"
#include "instrument/player/DynamicsPath.h"

namespace rosin::engine
{
namespace ROSIN_FILE_LOCAL
{

TEST(PlayableBand, SchellengLimitsFromTheStringsTensionDensityAndLosses)
{
    InstrumentKey key;
    const auto engine = buildEngine(key, ProgramExtras{}, 0, 1, 48000.0);
    const auto& strings = engine->instrument.config().strings;
    for (std::size_t k = 0; k < strings.size(); ++k)
    {
        const player::PlayableBand& band = engine->bands[k];
        ASSERT_TRUE(band.valid()) << strings[k].name;
        const double z0 = std::sqrt(strings[k].tension * strings[k].massPerLength);
        const double dmu = band.muStatic - band.muDynamic;
        const double v = 0.1, beta = 0.1;
        EXPECT_NEAR(band.maximumForce(v, beta), 2.0 * z0 * v / (beta * dmu), 1e-9) << strings[k].name;
        EXPECT_NEAR(band.minimumForce(v, beta), z0 * z0 * v * band.conductance / (2.0 * beta * beta * dmu),
                    1e-12)
            << strings[k].name;
        // A thermal law's mu_d is the classical curve's share of its mu_s (physics::frictionLimits).
        EXPECT_NEAR(band.muDynamic / band.muStatic, 0.35 / 1.2, 1e-12);
    }
}

TEST(PlayableBand, IsOpenAlongTheDynamicsPathOnEveryString)
{
    const player::DynamicsPath path;
    for (int instrument : {0, 1})
    {
        InstrumentKey key;
        key.instrument = instrument;
        const auto engine = buildEngine(key, ProgramExtras{}, 0, 1, 48000.0);
        const auto& strings = engine->instrument.config().strings;
        for (std::size_t k = 0; k < strings.size(); ++k)
        {
            const player::PlayableBand& band = engine->bands[k];
            for (double d = 0.0; d <= 1.0001; d += 0.25)
            {
                const auto bow = player::musicalBow(path, band, d, 0.5, 1.0);
                // The edges as the lab measured them (PlayableBand::lowerEdge, upperEdge).
                const double low = band.lowerEdge * band.minimumForce(bow.bowSpeed, bow.beta);
                const double high = band.upperEdge * band.maximumForce(bow.bowSpeed, bow.beta);
                std::printf(
                    "[ figures  ] %-22s d %.2f: v_b %.3f m/s beta %.3f  F_min %.3f  F %.3f  F_max %.3f N\n",
                    strings[k].name.c_str(), d, bow.bowSpeed, bow.beta, low, bow.bowForce, high);
                EXPECT_LT(low, high) << strings[k].name << " d " << d;
                EXPECT_GT(bow.bowForce, low) << strings[k].name << " d " << d;
                EXPECT_GE(bow.bowForce, player::kMusicalForceMin);
                // Towards pp the force stops at its floor (kMusicalForceMin), which every string reaches
                // where the formula's band lies below it; from mf on every string plays inside the band.
                if (bow.bowForce > player::kMusicalForceMin || d >= 0.5)
                    EXPECT_LT(bow.bowForce, high) << strings[k].name << " d " << d;
            }
        }
    }
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::engine
