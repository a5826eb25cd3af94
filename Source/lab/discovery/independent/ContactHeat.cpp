#include "lab/discovery/independent/ContactHeat.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rosin::discovery
{

namespace
{
constexpr double kDepthPerRadius = 200.; ///< domain depth / a; far boundary at ambient
} // namespace

ContactHeat::ContactHeat(double radius, double layerThickness, const HeatMaterials& materials, double dt,
                         const HeatGrid& grid)
    : radius_(radius), delta_(layerThickness), dt_(dt), length_(8.0 * radius / (3.0 * std::numbers::pi)),
      materials_(materials), grid_(grid)
{
    const double area = std::numbers::pi * radius * radius;
    contactCap_ = materials.layer.volumetricHeatCapacity * area * layerThickness;
    moving_ = makeSide(materials.moving);
    stationary_ = makeSide(materials.stationary);
    reduce(moving_, 1.0, 0.0);
    reduce(stationary_, 1.0, 0.0);
}

// Finite volumes in the widening section: node j at depth x_{j+1}; the capacity of [x1, x2] is
// rho c pi a^2 l/3 [(1+x2/l)^3 - (1+x1/l)^3] and the conductance K pi a^2 / (l [1/(1+x1/l) - 1/(1+x2/l)]),
// exact for the steady spherical-like profile. The contact node keeps each side's first half cell.
ContactHeat::Side ContactHeat::makeSide(const physics::ThermalMaterial& m)
{
    const double l = length_, area = std::numbers::pi * radius_ * radius_;
    auto volume = [&](double x1, double x2)
    { return area * l / 3.0 * (std::pow(1.0 + x2 / l, 3) - std::pow(1.0 + x1 / l, 3)); };
    auto conductance = [&](double x1, double x2)
    { return m.conductivity * area / (l * (1.0 / (1.0 + x1 / l) - 1.0 / (1.0 + x2 / l))); };

    std::vector<double> x{0.0};
    double h = grid_.surfaceCell * std::sqrt(m.diffusivity() * dt_);
    while (x.back() < kDepthPerRadius * radius_)
    {
        x.push_back(x.back() + h);
        h *= grid_.growth;
    }
    Side s;
    const std::size_t n = x.size() - 1; // nodes 1..n-1 are free, x[n] is the ambient boundary
    for (std::size_t j = 1; j < n; ++j)
        s.cap.push_back(m.volumetricHeatCapacity * volume(0.5 * (x[j - 1] + x[j]), 0.5 * (x[j] + x[j + 1])));
    for (std::size_t j = 1; j <= n; ++j)
        s.cond.push_back(conductance(x[j - 1], x[j]));
    s.temp.assign(s.cap.size(), 0.0);
    s.rhs.assign(s.cap.size(), 0.0);
    s.halfCell = m.volumetricHeatCapacity * volume(0.0, 0.5 * x[1]);
    contactCap_ += s.halfCell;
    return s;
}

void ContactHeat::reduce(Side& s, double capacityFactor, double sinkRate) const
{
    const std::size_t n = s.cap.size();
    s.invPivot.assign(n, 0.0);
    s.carry.assign(n, 0.0);
    double below = 0.0; // cond[j+1]^2 / pivot[j+1]
    for (std::size_t j = n; j-- > 0;)
    {
        const double pivot = s.cap[j] * (capacityFactor / dt_ + sinkRate) + s.cond[j] + s.cond[j + 1] - below;
        s.invPivot[j] = 1.0 / pivot;
        s.carry[j] = j + 1 < n ? s.cond[j + 1] * s.invPivot[j + 1] : 0.0;
        below = s.cond[j] * s.cond[j] / pivot;
    }
    s.contactLoad = s.cond[0] - below;
}

void ContactHeat::forward(Side& s, double invDt) noexcept
{
    double deeper = 0.0;
    for (std::size_t j = s.cap.size(); j-- > 0;)
    {
        s.rhs[j] = s.cap[j] * invDt * s.temp[j] + s.carry[j] * deeper;
        deeper = s.rhs[j];
    }
}

void ContactHeat::back(Side& s, double contactT) noexcept
{
    double shallower = contactT;
    for (std::size_t j = 0; j < s.cap.size(); ++j)
    {
        s.temp[j] = (s.rhs[j] + s.cond[j] * shallower) * s.invPivot[j];
        shallower = s.temp[j];
    }
}

ContactHeat::Prediction ContactHeat::predict(double slidingSpeed) noexcept
{
    const double invDt = 1.0 / dt_;
    const double washout = std::abs(slidingSpeed) / radius_;
    if (washout != washout_)
    {
        reduce(moving_, 1.0, washout);
        washout_ = washout;
    }
    forward(moving_, invDt);
    forward(stationary_, invDt);
    advection_ = materials_.layer.volumetricHeatCapacity * grid_.advectionWidth * radius_ * delta_ *
                 std::abs(slidingSpeed);
    // The moving side's half cell in the contact node is washed out like the rest of that side.
    pivot0_ = contactCap_ * invDt + advection_ + moving_.halfCell * washout + moving_.contactLoad +
              stationary_.contactLoad;
    const double r0 = contactCap_ * invDt * contact_ +
                      moving_.cond[0] * moving_.rhs[0] * moving_.invPivot[0] +
                      stationary_.cond[0] * stationary_.rhs[0] * stationary_.invPivot[0];
    free_ = r0 / pivot0_;
    return {free_, 1.0 / pivot0_};
}

void ContactHeat::finish(double power) noexcept
{
    contact_ = free_ + power / pivot0_;
    back(moving_, contact_);
    back(stationary_, contact_);
}

void ContactHeat::reset() noexcept
{
    contact_ = 0.0;
    if (washout_ != 0.0)
    {
        reduce(moving_, 1.0, 0.0);
        washout_ = 0.0;
    }
    for (Side* s : {&moving_, &stationary_})
    {
        std::fill(s->temp.begin(), s->temp.end(), 0.0);
        std::fill(s->rhs.begin(), s->rhs.end(), 0.0);
    }
}

// The fixed point of predict/finish at a constant speed: the same chain without its capacity terms.
double ContactHeat::steadyRise(double speed) const
{
    Side moving = moving_, stationary = stationary_;
    reduce(moving, 0.0, std::abs(speed) / radius_);
    reduce(stationary, 0.0, 0.0);
    const double adv =
        materials_.layer.volumetricHeatCapacity * grid_.advectionWidth * radius_ * delta_ * std::abs(speed);
    return 1.0 /
           (adv + moving.halfCell * std::abs(speed) / radius_ + moving.contactLoad + stationary.contactLoad);
}

double ContactHeat::continuumConductance(double speed) const
{
    const double v = std::abs(speed), a = radius_;
    const double pi = std::numbers::pi;
    return materials_.layer.volumetricHeatCapacity * grid_.advectionWidth * a * delta_ * v +
           3.0 * pi * pi / 8.0 * a * (materials_.stationary.conductivity + materials_.moving.conductivity) +
           pi * a * a * materials_.moving.effusivity() * std::sqrt(v / a);
}

} // namespace rosin::discovery
