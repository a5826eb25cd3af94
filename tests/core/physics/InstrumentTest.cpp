// Four strings on one bridge (BowedInstrument): the shared body stays passive, and a string set ringing
// passes energy through the bridge to the others (sympathetic resonance), which a rigid bridge never does.
#include <gtest/gtest.h>

#include "core/physics/instrument/BowedInstrument.h"

using namespace rosin::physics;

namespace ROSIN_FILE_LOCAL
{
/// Bow one string for 50 ms (a Guettler attack with the classical law), lift the bow, let everything ring.
struct Ringing
{
    double initialEnergy = 0.0;
    double worstRise = 0.0; ///< largest sample-to-sample rise of the total stored energy, / initial energy
    std::vector<double> others; ///< stored energy of each string after 0.5 s
};

Ringing ringAfterStroke(InstrumentConfig cfg, int plucked)
{
    cfg.friction = FrictionModel::Classical;
    BowedInstrument instrument;
    const double fs = 48000.0;
    instrument.prepare(cfg, fs);
    const int n = instrument.stringCount();
    std::vector<BowInput> in(n, BowInput{0.0, 0.0, 0.0899, 1.0});
    std::vector<VoiceSample> out(n);
    // A short down-bow on one string: 50 ms of bowing, then the bow leaves.
    for (int k = 0; k < 2400; ++k)
    {
        in[plucked] = {1.0, std::min(0.1, 1.56 * k / fs), 0.0899, 1.0};
        instrument.step(in.data(), out.data());
    }
    in[plucked] = {0.0, 0.0, 0.0899, 1.0};
    Ringing r;
    instrument.step(in.data(), out.data());
    r.initialEnergy = instrument.storedEnergy();
    double previous = r.initialEnergy;
    for (int k = 0; k < static_cast<int>(0.5 * fs); ++k)
    {
        instrument.step(in.data(), out.data());
        const double e = instrument.storedEnergy();
        r.worstRise = std::max(r.worstRise, (e - previous) / r.initialEnergy);
        previous = e;
    }
    for (int i = 0; i < n; ++i)
        r.others.push_back(instrument.voice(i).storedEnergy());
    return r;
}

TEST(Instrument, SharedBodyStaysPassive)
{
    const auto r = ringAfterStroke(celloInstrument(), 2);
    EXPECT_GT(r.initialEnergy, 0.0);
    // The other strings' forces reach each junction one sample late through the body; the coupling is a few
    // 1e-4 of the string's own compliance, so any energy it creates must stay far below a part in 1e6.
    EXPECT_LT(r.worstRise, 1e-6);
    std::printf("[figure] cello instrument ringing: worst one-sample energy rise %.1e of E0\n", r.worstRise);
}

TEST(Instrument, BridgeCarriesSympatheticResonance)
{
    auto rigid = celloInstrument();
    rigid.body = rigidBody();
    const auto withBody = ringAfterStroke(celloInstrument(), 2); // bow the D3 string
    const auto withoutBody = ringAfterStroke(rigid, 2);
    for (int i : {0, 1, 3})
    {
        EXPECT_GT(withBody.others[i], 1e-12) << "string " << i;  // the body passed energy on
        EXPECT_EQ(withoutBody.others[i], 0.0) << "string " << i; // a rigid bridge passes nothing
    }
    // Strings with harmonics in common with D3 (146.8 Hz) take up far more: G2's third harmonic (294 Hz) is
    // D3's second, A3's second (440 Hz) is D3's third; C2 (65.4 Hz) shares none below 580 Hz.
    EXPECT_GT(withBody.others[1], 10.0 * withBody.others[0]);
    EXPECT_GT(withBody.others[3], 10.0 * withBody.others[0]);
    std::printf(
        "[figure] after bowing D3 on the cello body: energy in C2 %.2e J, G2 %.2e J, A3 %.2e J (D3 %.2e J)\n",
        withBody.others[0], withBody.others[1], withBody.others[3], withBody.others[2]);
}

} // namespace ROSIN_FILE_LOCAL
