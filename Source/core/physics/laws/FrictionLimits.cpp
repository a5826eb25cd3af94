#include "core/physics/laws/FrictionLimits.h"

namespace rosin::physics
{

namespace
{
constexpr double kReferenceForce = 1.0; ///< N, where mu_s is read (force-independent for Coulomb contacts)
constexpr double kClassicalDynamic = 0.35;
constexpr double kClassicalDynamicToStatic = 0.35 / 1.2;
} // namespace

FrictionLimits frictionLimits(FrictionModel model, const ContactParameters& contact, double sampleRate)
{
    auto law = makeFrictionLaw(model, contact);
    law->prepare(sampleRate);
    law->reset();
    FrictionLimits limits;
    limits.muStatic = law->staticCoefficient(kReferenceForce);
    const bool curve = model == FrictionModel::Classical || model == FrictionModel::Reconstructed;
    limits.muDynamic = curve ? kClassicalDynamic : kClassicalDynamicToStatic * limits.muStatic;
    return limits;
}

} // namespace rosin::physics
