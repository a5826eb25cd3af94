// The share of the Bow force parameter each string is bowed with (engine::bowForceShare): Z0 over the cello
// C string's, so that every string of either instrument sits at the same fraction of Schelleng's maximum
// force 2 Z0 v_b / (beta (mu_s - mu_d)). This checks the engine's shares against that definition, from the
// strings' tension and linear density (Z0 = sqrt(T mu)); what the shares do to the sound (open strings within
// 2.4 cents at the default force, 12-37 cents flat without them) is PluginPitch's.
#include <gtest/gtest.h>

#include <cmath>

#include "instrument/engine/Engine.h"

namespace rosin::engine
{
namespace ROSIN_FILE_LOCAL
{

double impedanceFromTensionAndDensity(const physics::StringParameters& s)
{
    return std::sqrt(s.tension * s.massPerLength);
}

TEST(BowForceShare, EveryStringOfEitherInstrumentSitsAtTheSameFractionOfItsSchellengMaximum)
{
    const double reference = impedanceFromTensionAndDensity(physics::stringFromCatalogue("cello-C2"));
    for (int instrument : {0, 1})
    {
        InstrumentKey key;
        key.instrument = instrument;
        const auto engine = buildEngine(key, ProgramExtras{}, 0, 1, 48000.0);
        const auto& strings = engine->instrument.config().strings;
        for (std::size_t k = 0; k < strings.size(); ++k)
        {
            const double z0 = impedanceFromTensionAndDensity(strings[k]);
            EXPECT_NEAR(engine->forceShares[k], z0 / reference, 1e-9 * z0 / reference) << strings[k].name;
        }
        EXPECT_LT(engine->forceShares[strings.size() - 1], engine->forceShares[0]);
    }
    EXPECT_DOUBLE_EQ(bowForceShare(reference), 1.0);
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::engine
