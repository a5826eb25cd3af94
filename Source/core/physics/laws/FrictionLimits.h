#pragma once
// The two friction coefficients Schelleng's and Guettler's limits are written with ([Notes §6]), for one of
// the six laws. mu_s is the law's limiting static coefficient at 1 N, at ambient (FrictionLaw::
// staticCoefficient after prepare). mu_d: the curve laws' limit at high sliding speed (0.35 for both,
// [Galluzzo2017] eqs. 1-2); the thermal laws are calibrated so that steady sliding reproduces a curve, and
// we take the classical curve's ratio mu_d/mu_s = 0.35/1.2 of their own mu_s (exact for plastic and
// viscous, calibrated on the classical curve; an assumption for the modified laws, whose power-law steady
// curve has no finite limit). Off the audio thread: prepares a law (~25 ms for a thermal one).
#include "core/physics/laws/FrictionLawFactory.h"

namespace rosin::physics
{

struct FrictionLimits
{
    double muStatic = 0.0;
    double muDynamic = 0.0;
};

FrictionLimits frictionLimits(FrictionModel model, const ContactParameters& contact, double sampleRate);

} // namespace rosin::physics
