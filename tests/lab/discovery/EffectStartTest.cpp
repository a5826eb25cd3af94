// Where rosin discover fits an effect from (EffectSearch.h, effectStartNuisance): the rig's parameters as
// stated, since a calibration may have bent them to mimic the effect, but the parameters no effect can take
// the form of (the measurement chain's and the string's tension) as calibrated. The second test checks the
// premise for the tension against the models the catalog builds: no effect retunes the string.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "lab/discovery/EffectCatalog.h"
#include "lab/discovery/NuisanceParameters.h"
#include "lab/discovery/SimulationModel.h"
#include "lab/discovery/discover/EffectSearch.h"

using namespace rosin::discovery;

namespace ROSIN_FILE_LOCAL
{
std::size_t indexOf(const std::string& name)
{
    const auto& all = nuisanceParameters();
    for (std::size_t j = 0; j < all.size(); ++j)
        if (all[j].prior.name == name)
            return j;
    ADD_FAILURE() << "no nuisance parameter " << name;
    return all.size();
}

// The angular frequencies of the string's first 12 transverse modes (stiffness included) in `model`.
std::vector<double> modeFrequencies(const SimulationModel& model)
{
    const auto cfg = voiceConfig(model);
    std::vector<double> w;
    for (int n = 1; n <= 12; ++n)
        w.push_back(cfg.string.modeAngularFrequency(n, cfg.string.length));
    return w;
}

// Every corner of an effect's parameter box: each continuous parameter at its min and max, every choice.
std::vector<std::vector<double>> corners(const Effect& effect)
{
    std::vector<std::vector<double>> points{{}};
    for (const auto& p : effect.parameters)
    {
        std::vector<double> values;
        if (p.choices.empty())
            values = {p.min, p.max};
        else
            for (std::size_t c = 0; c < p.choices.size(); ++c)
                values.push_back(static_cast<double>(c));
        std::vector<std::vector<double>> next;
        for (const auto& point : points)
            for (double v : values)
            {
                next.push_back(point);
                next.back().push_back(v);
            }
        points = next;
    }
    return points;
}

TEST(EffectStart, TuningAndChainKeepTheirCalibrationTheRigsParametersStartAsStated)
{
    const NuisanceValues stated{};
    NuisanceValues calibrated;
    calibrated.contactRadius = 1.08;
    calibrated.rosinConductivity = 0.9;
    calibrated.rosinHeatCapacity = 1.1;
    calibrated.tension = 1.01;
    calibrated.stringLoss = 1.15;
    calibrated.sensorGain = 1.02;
    calibrated.sensorBandwidth = 0.2;
    calibrated.sensorDelay = 1e-4;
    const std::vector<std::size_t> active{indexOf("contactRadius"), indexOf("sensorDelay")};

    const NuisanceValues start = effectStartNuisance(stated, calibrated, active);
    // The rig's parameters an effect can mimic start as stated (the string's losses too: extra damping).
    EXPECT_EQ(start.contactRadius, stated.contactRadius);
    EXPECT_EQ(start.rosinConductivity, stated.rosinConductivity);
    EXPECT_EQ(start.rosinHeatCapacity, stated.rosinHeatCapacity);
    EXPECT_EQ(start.stringLoss, stated.stringLoss);
    // The tuning and the chain keep their calibration...
    EXPECT_EQ(start.tension, calibrated.tension);
    EXPECT_EQ(start.sensorGain, calibrated.sensorGain);
    EXPECT_EQ(start.sensorBandwidth, calibrated.sensorBandwidth);
    // ...unless they are refitted with the effect, which then starts them as stated like the others.
    EXPECT_EQ(start.sensorDelay, stated.sensorDelay);

    const NuisanceValues tensionActive = effectStartNuisance(stated, calibrated, {indexOf("tension")});
    EXPECT_EQ(tensionActive.tension, stated.tension);
    EXPECT_EQ(tensionActive.sensorDelay, calibrated.sensorDelay);
}

TEST(EffectStart, NoEffectOfTheCatalogRetunesTheStringTheTensionDoes)
{
    const SimulationModel stated;
    const std::vector<double> reference = modeFrequencies(stated);
    for (const Effect& effect : effectCatalog())
        for (const auto& values : corners(effect))
        {
            SimulationModel model;
            applyEffect(effect, values, model);
            const std::vector<double> w = modeFrequencies(model);
            for (std::size_t n = 0; n < w.size(); ++n)
                EXPECT_EQ(w[n], reference[n]) << describeEffect(effect, values) << ", mode " << n + 1;
        }
    // The flag's other side: the tension is what tunes the string (f ~ sqrt(P), stiffness aside: within
    // 1e-4 over the first 12 modes of the cello D).
    SimulationModel tuned;
    tuned.nuisance.tension = 1.01;
    const std::vector<double> w = modeFrequencies(tuned);
    for (std::size_t n = 0; n < w.size(); ++n)
        EXPECT_NEAR(w[n] / reference[n], std::sqrt(1.01), 1e-4) << "mode " << n + 1;
    EXPECT_TRUE(nuisanceParameters()[indexOf("tension")].startsCalibrated);
    EXPECT_FALSE(nuisanceParameters()[indexOf("stringLoss")].startsCalibrated);
    EXPECT_FALSE(nuisanceParameters()[indexOf("contactRadius")].startsCalibrated);
}

} // namespace ROSIN_FILE_LOCAL
