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

void validateBow(const BowParameters& bow, const std::string& where)
{
    const auto fail = [&](const std::string& field, const std::string& expected, double got)
    {
        throw std::invalid_argument(where + ": bow." + field + " must be " + expected + ", not " +
                                    std::to_string(got));
    };
    if (!(bow.width >= 0.0 && bow.width <= 0.03))
        fail("width", "0..0.03 m", bow.width);
    if (bow.compliantHair)
    {
        if (!(bow.hairStiffness >= 1.0e2 && bow.hairStiffness <= 1.0e8))
            fail("hairStiffness", "1e2..1e8 N/m", bow.hairStiffness);
        if (!(bow.hairDamping >= 0.1 && bow.hairDamping <= 1.0e4))
            fail("hairDamping", "0.1..1e4 kg/s", bow.hairDamping);
    }
}

} // namespace rosin::physics
