#include "core/physics/bow/BowParameters.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace rosin::physics
{

namespace
{
// One horsehair: radius 0.08 mm ([Notes §8.3]), Young's modulus 6 GPa, the middle of horsehair's 3-9 GPa
// ([Notes] materials table), density 1300 kg/m^3 (keratin fibre, Robbins, "Chemical and Physical Behavior
// of Human Hair").
constexpr double kHairRadius = 0.08e-3;
constexpr double kHairModulus = 6.0e9;
constexpr double kHairDensity = 1300.0;
// Hairs that touch the string at once: one layer of the ribbon, 50 of about 200 (Woodhouse, euphonics.org
// 9.7.3, after Pitteroff).
constexpr double kActiveHairs = 50.0;
// Free hair from the contact to the frog and to the tip at mid-bow of a ~0.6 m ribbon.
constexpr double kToFrog = 0.3, kToTip = 0.3;
} // namespace

BowParameters horsehairBow(double width)
{
    const double area = std::numbers::pi * kHairRadius * kHairRadius;
    BowParameters bow;
    bow.width = width;
    bow.compliantHair = true;
    // Both free lengths stretch in parallel: k = n E A (1/l_frog + 1/l_tip). Above k / r the hair's
    // longitudinal waves carry the force away instead: r = n 2 A sqrt(E rho), one wave each way.
    bow.hairStiffness = kActiveHairs * kHairModulus * area * (1.0 / kToFrog + 1.0 / kToTip);
    bow.hairDamping = kActiveHairs * 2.0 * area * std::sqrt(kHairModulus * kHairDensity);
    return bow;
}

double ribbonSlipNoise()
{
    return 1.0 / std::sqrt(kActiveHairs);
}

void validateBow(const BowParameters& bow, const std::string& where)
{
    const auto check = [&](const char* field, const Range& range, double got)
    {
        if (!range.contains(got))
            throw std::invalid_argument(where + ": bow." + field + " must be " + range.describe() + ", not " +
                                        formatNumber(got));
    };
    check("width", limits::bowWidth, bow.width);
    check("slipNoise", limits::slipNoise, bow.slipNoise);
    if (bow.compliantHair)
    {
        check("hairStiffness", limits::hairStiffness, bow.hairStiffness);
        check("hairDamping", limits::hairDamping, bow.hairDamping);
    }
}

} // namespace rosin::physics
