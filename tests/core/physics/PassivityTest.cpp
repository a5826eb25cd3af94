// Passivity: with no bow, the stored mechanical energy of string (transverse and torsional) and body never
// increases, sample after sample. The string is set ringing by a short force pulse, then left alone.
#include <gtest/gtest.h>

#include <cmath>

#include "core/physics/voice/BowedStringVoice.h"
#include "support/TestLaws.h"

using namespace rosin;
using namespace rosin::physics;

namespace ROSIN_FILE_LOCAL
{
void expectEnergyNeverIncreases(const VoiceConfig& cfg, double fs)
{
    std::vector<double> pulse(48, 0.0);
    for (std::size_t i = 0; i < pulse.size(); ++i)
        pulse[i] = std::sin(M_PI * i / pulse.size()); // 1 ms half-sine of 1 N
    BowedStringVoice voice;
    voice.prepare(cfg, std::make_unique<test::PrescribedForceLaw>(pulse), fs);
    for (std::size_t k = 0; k < pulse.size(); ++k)
        voice.step({0.0, 0.0, 0.0899, 1.0});
    double previous = voice.storedEnergy();
    const double initial = previous;
    double worstRise = 0.0;
    for (int k = 0; k < static_cast<int>(fs); ++k)
    {
        voice.step({0.0, 0.0, 0.0899, 1.0});
        const double e = voice.storedEnergy();
        worstRise = std::max(worstRise, (e - previous) / initial);
        previous = e;
    }
    EXPECT_GT(initial, 0.0);
    EXPECT_LE(worstRise, 1e-12) << "energy rose between two samples";
    EXPECT_LT(previous, initial);
    std::printf("[figure] passivity (%s body, %.0f Hz): E0 %.3e J, after 1 s %.3e J, worst rise %.1e of E0\n",
                cfg.body.name.c_str(), fs, initial, previous, worstRise);
}

TEST(Passivity, RigidBridgeWithTorsion)
{
    VoiceConfig cfg;
    cfg.string = stringFromCatalogue("cello-D3");
    expectEnergyNeverIncreases(cfg, 48000.0);
}

TEST(Passivity, CelloBody)
{
    VoiceConfig cfg;
    cfg.string = stringFromCatalogue("cello-D3");
    cfg.body = celloBody();
    expectEnergyNeverIncreases(cfg, 48000.0);
    expectEnergyNeverIncreases(cfg, 44100.0);
}

} // namespace ROSIN_FILE_LOCAL
