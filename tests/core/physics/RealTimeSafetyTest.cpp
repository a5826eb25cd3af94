// Real-time safety: after prepare(), stepping a voice performs no heap allocation, whatever the friction
// law and whatever the gesture does (beta and finger changes included). Global operator new is replaced in
// this test binary to count allocations while a flag is set.
#include <gtest/gtest.h>

#include "core/physics/friction/CurveFrictionLaw.h"
#include "core/physics/instrument/BowedInstrument.h"
#include "core/physics/laws/FrictionLawFactory.h"
#include "core/physics/voice/BowedStringVoice.h"
#include "support/AllocationCounter.h"
#include "support/TestLaws.h"

namespace rosin::test
{
/// Steps through a gesture that exercises every per-sample path: attack, slip, beta and finger glides.
long allocationsDuringSteps(physics::BowedStringVoice& voice)
{
    AllocationCounter counter;
    for (int k = 0; k < 20000; ++k)
    {
        const double t = k / 48000.0;
        voice.step({0.5 + 0.4 * std::sin(7.0 * t), std::min(0.1, 0.5 * t), 0.08 + 0.05 * t, 1.0 - 0.3 * t});
    }
    return counter.count();
}
} // namespace rosin::test

TEST(RealTimeSafety, CounterSeesAllocations)
{
    rosin::test::AllocationCounter counter;
    auto* p = new int(3);                   // the counter must notice this, or the other tests prove nothing
    asm volatile("" : : "r"(p) : "memory"); // keep the compiler from eliding the allocation
    delete p;
    EXPECT_EQ(counter.count(), 1);
}

TEST(RealTimeSafety, StepAllocatesNothingWithCurveLaws)
{
    using namespace rosin::physics;
    VoiceConfig cfg;
    cfg.string = stringFromCatalogue("cello-D3");
    cfg.body = celloBody();
    for (int law = 0; law < 2; ++law)
    {
        BowedStringVoice voice;
        if (law == 0)
            voice.prepare(cfg, std::make_unique<ClassicalFrictionLaw>(ClassicalCurve{}, "classical"),
                          48000.0);
        else
            voice.prepare(cfg,
                          std::make_unique<ReconstructedFrictionLaw>(ReconstructedCurve{}, "reconstructed"),
                          48000.0);
        EXPECT_EQ(rosin::test::allocationsDuringSteps(voice), 0) << "law " << law;
    }
}

TEST(RealTimeSafety, StepAllocatesNothingWithEveryLaw)
{
    using namespace rosin::physics;
    VoiceConfig cfg;
    cfg.string = stringFromCatalogue("cello-D3");
    cfg.body = celloBody();
    for (const auto& name : frictionModelNames())
    {
        BowedStringVoice voice;
        voice.prepare(cfg, makeFrictionLaw(frictionModelFromName(name), galluzzoContact()), 48000.0);
        EXPECT_EQ(rosin::test::allocationsDuringSteps(voice), 0) << name;
    }
}

TEST(RealTimeSafety, OutputStaysFiniteUnderWildInput)
{
    using namespace rosin::physics;
    VoiceConfig cfg;
    cfg.string = stringFromCatalogue("cello-D3");
    cfg.body = celloBody();
    for (const auto& name : frictionModelNames())
    {
        BowedStringVoice voice;
        voice.prepare(cfg, makeFrictionLaw(frictionModelFromName(name), galluzzoContact()), 48000.0);
        std::uint32_t state = 12345;
        auto uniform = [&] { return (state = state * 1664525u + 1013904223u) / 4294967296.0; };
        double worst = 0.0, force = 1.0, speed = 0.0, beta = 0.1, finger = 1.0;
        for (int k = 0; k < 48000; ++k)
        {
            // Every input jumps at random within and beyond its range, every 64 samples.
            if (k % 64 == 0)
                force = 25 * uniform() - 2, speed = 10 * uniform() - 5, beta = uniform() - 0.2,
                finger = 1.5 * uniform();
            const auto out = voice.step({force, speed, beta, finger});
            ASSERT_TRUE(std::isfinite(out.bridgeForce)) << name << " at sample " << k;
            worst = std::max(worst, std::abs(out.bridgeForce));
        }
        EXPECT_LT(worst, 1e4) << name;
        std::printf("[figure] wild input, %s: largest |bridge force| %.1f N\n", name.c_str(), worst);
    }
}

TEST(RealTimeSafety, InstrumentStepAllocatesNothing)
{
    using namespace rosin::physics;
    for (const auto& cfg : {celloInstrument(), violinInstrument()})
    {
        BowedInstrument instrument;
        instrument.prepare(cfg, 48000.0);
        std::vector<BowInput> in(instrument.stringCount(), BowInput{0.8, 0.0, 0.1, 1.0});
        std::vector<VoiceSample> out(instrument.stringCount());
        rosin::test::AllocationCounter counter;
        for (int k = 0; k < 10000; ++k)
        {
            for (auto& b : in)
                b.bowVelocity = std::min(0.1, 0.5 * k / 48000.0), b.fingerRatio = 1.0 - 0.2 * k / 10000.0;
            instrument.step(in.data(), out.data());
        }
        EXPECT_EQ(counter.count(), 0) << cfg.name;
    }
}
