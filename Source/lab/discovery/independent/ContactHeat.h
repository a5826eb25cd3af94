#pragma once
// The independent generator's heat balance for the rosin contact ([Notes §2.3], §2.3a; [Smith2000]: heating
// balanced by conduction into both solids, advection of cold rosin, and the layer's heat capacity), written
// as a finite-difference chain, not Rosin's Green's-function convolution:
//
//   moving solid (rod)  ...  node 2  node 1 | contact node | node 1  node 2  ...  stationary solid (string)
//
// The contact node holds the softened layer (rho c pi a^2 delta) and the two surfaces' half cells; it takes
// the frictional power P and loses rho c a delta |dv| T to the rosin advected through it (width a: the layer
// shears uniformly, so half of a 2a-wide disc's flow passes). Each solid is a 1-D conductor whose section
// widens with depth, A(x) = pi a^2 (1 + x/l)^2 with l = 8a/(3 pi): at audio time scales (depth << a) that is
// 1-D conduction through the contact disc, and in steady state it has exactly the disc's mean steady
// conductance (3 pi^2/8) K a ([Notes] eq. 2.7, the integral of the disc Green's function). The grid is
// geometric (by default half a diffusion length of one step at the surface, x1.25 per node; 200 a deep).
//
// The moving solid conducts like the stationary one while the contact sticks; while it slides, its surface
// patch is carried away and replaced by fresh material at ambient, which this model lumps as a washout of
// the moving side's profile excess at the rate |dv| / a (one contact radius of sliding renews it), taken
// into the implicit step as a sink on the moving side's nodes: a step leaves 1 / (1 + |dv| dt / a) ~
// exp(-|dv| dt / a) of the excess. (Applied as a multiplication after the step instead, the split makes the
// steady sliding conductance ~5 % low at 1 m/s and 88.2 kHz; in the step it is exact in steady state.)
//
// Steps are backward Euler on the whole chain, eliminated from both deep ends towards the contact node, so
// the contact temperature of a step is an explicit affine function of that step's power, T = free + P/pivot,
// which the friction solve uses to be implicit in P without iterating the chain.
#include <vector>

#include "core/physics/thermal/ThermalMaterial.h"

namespace rosin::discovery
{

struct HeatMaterials
{
    physics::ThermalMaterial layer;      ///< the softened rosin layer (capacity, advection)
    physics::ThermalMaterial stationary; ///< the string's (rosin-coated) surface
    physics::ThermalMaterial moving;     ///< the rod or hair that slides through the contact
};

/// The discretisation's own choices (a generator family's member draws them; GeneratorMember.h).
struct HeatGrid
{
    double surfaceCell = 0.5;    ///< first cell, x one step's diffusion length sqrt(D dt)
    double growth = 1.25;        ///< spacing ratio from node to node
    double advectionWidth = 1.0; ///< the width of rosin carried through the contact, x its radius
};

class ContactHeat
{
  public:
    /// A contact of radius a (m) and layer thickness delta (m), stepped at dt (s).
    ContactHeat(double radius, double layerThickness, const HeatMaterials& materials, double dt,
                const HeatGrid& grid = {});

    /// Contact temperature rise of this step as free + perWatt x P.
    struct Prediction
    {
        double free = 0.0;    ///< K, with no heating this step
        double perWatt = 0.0; ///< K/W
        double at(double power) const noexcept { return free + perWatt * power; }
    };
    /// Eliminates the chain towards the contact for a step whose advection and washout run at the sliding
    /// speed `slidingSpeed` (m/s; the caller passes the last step's, one step of lag at 2 x 44.1 kHz).
    Prediction predict(double slidingSpeed) noexcept;
    /// Completes the step with its power P (W).
    void finish(double power) noexcept;
    double temperature() const noexcept { return contact_; } ///< K above ambient
    void reset() noexcept;

    /// Steady sliding at `speed` in THIS discretisation (the fixed point of predict/finish at constant
    /// speed): contact temperature rise per watt (K/W).
    double steadyRise(double speed) const;
    /// The continuous model's steady conductance (W/K): rho c a delta v + (3 pi^2/8) a (K_s + K_m)
    /// + pi a^2 e_m sqrt(v / a) (the moving side's washout profile solved in the widening section).
    double continuumConductance(double speed) const;
    double radius() const noexcept { return radius_; }

  private:
    struct Side
    {
        std::vector<double> cap;       ///< J/K of nodes 1..N (index 0..N-1)
        std::vector<double> cond;      ///< W/K: cond[j] joins node j-1 (contact for j = 0) and node j
        std::vector<double> invPivot;  ///< 1 / reduced pivot of node j
        std::vector<double> carry;     ///< cond[j+1] / pivot[j+1]: what node j takes of the deeper rhs
        std::vector<double> temp, rhs; ///< K rise; reduced right-hand side
        double contactLoad = 0.0;      ///< cond[0] - cond[0]^2 / pivot[0]
        double halfCell = 0.0;         ///< J/K: the side's first half cell, part of the contact node
    };
    Side makeSide(const physics::ThermalMaterial& m); ///< also adds its half cell to the contact node
    /// Reduced pivots with the capacity term cap/dt x capacityFactor (1 when stepping, 0 for the steady
    /// state) and a sink cap x sinkRate (the washout, 1/s).
    void reduce(Side& side, double capacityFactor, double sinkRate) const;
    static void forward(Side& side, double invDt) noexcept;
    static void back(Side& side, double contactT) noexcept;

    double radius_, delta_, dt_, length_;
    HeatMaterials materials_;
    HeatGrid grid_;
    double contactCap_ = 0.0;
    Side moving_, stationary_;
    double contact_ = 0.0;
    double pivot0_ = 1.0, advection_ = 0.0, free_ = 0.0;
    double washout_ = 0.0; ///< 1/s, the moving side's reduction was made for this rate
};

} // namespace rosin::discovery
