// The rig as a linear system behind the junction: [Smith2000] eq. 1 holds sample by sample, the contact sees
// the load line of a free mass, bad parameters are named, and step() never allocates.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/physics/friction/CurveFrictionLaw.h"
#include "core/physics/rig/RigTestSupport.h"
#include "support/AllocationCounter.h"

using namespace rosin::physics;
using namespace rosin::test::rig;

TEST(OscillatorRig, DerivedConstantsFollowFrequencyQAndMass)
{
    const OscillatorRigParameters p{108.0, 20.0, 0.02};
    const double w = 2.0 * std::numbers::pi * 108.0;
    EXPECT_NEAR(p.stiffness(), 0.02 * w * w, 1e-9);
    EXPECT_NEAR(p.resistance(), 0.02 * w / 20.0, 1e-12);
}

TEST(OscillatorRig, ContactAdmittanceIsThatOfAMassOverOneStep)
{
    OscillatorRig rig;
    rig.prepare({}, makeFrictionLaw(FrictionModel::Classical, cantileverContact()), kSampleRate);
    // A mass m answers an impulse f T with a velocity step f T/m, sampled half before and half after (T/2m),
    // plus the band correction T/(2m) (OscillatorRig.h): T/m. The spring and damper change it by
    // (omega0 T)^2 ~ 2e-4.
    const double m = rig.parameters().modalMass;
    EXPECT_NEAR(rig.instantaneousAdmittance(), 1.0 / (kSampleRate * m), 1e-3 / (kSampleRate * m));
}

TEST(OscillatorRig, ForceSettlesWithinAFewSamplesOfACapture)
{
    // After slip -> stick, the holding force follows S x + R v_rod again within 24 samples (0.5 ms): the
    // admittance's zeros have |z| = 0.71 (OscillatorRig.h), so a capture's error falls by 0.71^24 ~ 2.5e-4.
    const RigRun run = seedRun(FrictionModel::Classical, cantileverContact(), 0.3);
    const OscillatorRigParameters p;
    int captures = 0;
    for (std::size_t k = 1; k + 24 < run.samples.size(); ++k)
    {
        if (run.samples[k - 1].sticking || !run.samples[k].sticking)
            continue;
        ++captures;
        const RigSample& s = run.samples[k + 24];
        ASSERT_TRUE(s.sticking);
        EXPECT_NEAR(s.frictionForce, p.stiffness() * s.displacement + p.resistance() * s.velocity, 0.01);
    }
    EXPECT_GE(captures, 8);
}

TEST(OscillatorRig, EquationOfMotionHoldsEverySample)
{
    // m x'' + R x' + S x = f ([Smith2000] eq. 1), through sticking, slipping and the transitions.
    const RigRun run = seedRun(FrictionModel::Classical, cantileverContact(), 0.2);
    const OscillatorRigParameters p;
    double worst = 0.0;
    for (const RigSample& s : run.samples)
    {
        const double residual = p.modalMass * s.acceleration + p.resistance() * s.velocity +
                                p.stiffness() * s.displacement - s.frictionForce;
        worst = std::max(worst, std::abs(residual));
    }
    EXPECT_LT(worst, 0.05); // N, against friction forces of up to 7.6 N
}

TEST(OscillatorRig, StickingOscillatorMovesWithTheRodAndTheSpringCarriesTheFriction)
{
    const RigRun run = seedRun(FrictionModel::Classical, cantileverContact(), 0.3);
    const OscillatorRigParameters p;
    int stuck = 0;
    for (std::size_t k = sampleAt(run, 0.1); k < run.samples.size(); ++k)
    {
        const RigSample& s = run.samples[k];
        // Stuck for more than 24 samples (the settling after a capture is tested above).
        if (!std::all_of(&run.samples[k - 24], &s + 1, [](const RigSample& r) { return r.sticking; }))
            continue;
        ++stuck;
        EXPECT_NEAR(s.velocity, CantileverLoad::rodSpeed, 1e-9);
        // a = 0 while stuck, so f = S x + R v_rod: the friction a static test would read off the spring.
        EXPECT_NEAR(s.frictionForce, p.stiffness() * s.displacement + p.resistance() * s.velocity, 0.02);
        // and never beyond the static limit of eq. 2, mu(0) = 1.2.
        EXPECT_LE(std::abs(s.frictionCoefficient()), 1.2 + 1e-9);
    }
    EXPECT_GT(stuck, 1000);
}

TEST(OscillatorRig, WithoutLoadNothingMoves)
{
    const RigRun run = [&]
    {
        return runRig({}, makeFrictionLaw(FrictionModel::Plastic, cantileverContact()), kSampleRate, 0.0,
                      CantileverLoad::rodSpeed, 0.05);
    }();
    for (const RigSample& s : run.samples)
    {
        EXPECT_EQ(s.frictionForce, 0.0);
        EXPECT_EQ(s.displacement, 0.0);
    }
}

TEST(OscillatorRig, BadParametersAreNamed)
{
    OscillatorRig rig;
    auto expectField = [&](OscillatorRigParameters p, const std::string& field)
    {
        try
        {
            rig.prepare(p, makeFrictionLaw(FrictionModel::Classical, cantileverContact()), kSampleRate);
            FAIL() << "accepted a bad " << field;
        }
        catch (const std::invalid_argument& e)
        {
            EXPECT_NE(std::string(e.what()).find("\"" + field + "\""), std::string::npos) << e.what();
        }
    };
    expectField({0.0, 20.0, 0.02}, "frequency");
    expectField({108.0, 0.1, 0.02}, "qualityFactor");
    expectField({108.0, 20.0, -1.0}, "modalMass");
    expectField({108.0, 20.0, std::nan("")}, "modalMass");
}

TEST(OscillatorRig, ResetAndStepNeverAllocate)
{
    for (FrictionModel model : {FrictionModel::Classical, FrictionModel::Plastic, FrictionModel::Viscous})
    {
        OscillatorRig rig;
        rig.prepare({}, makeFrictionLaw(model, cantileverContact()), kSampleRate);
        rosin::test::AllocationCounter counter;
        rig.reset();
        for (int k = 0; k < 4800; ++k)
            rig.step({CantileverLoad::normalForce, CantileverLoad::rodSpeed});
        EXPECT_EQ(counter.count(), 0) << frictionModelName(model);
    }
}
