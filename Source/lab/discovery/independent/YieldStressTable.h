#pragma once
// The plastic law's material function tau_y(T) ([Smith2000] eq. 4: friction = contact area x shear yield
// stress of the softened rosin), calibrated the independent generator's own way: steady sliding on the
// calibration rig ([Galluzzo2017] Table 2: 500 um at 3 N, 10 um layer) must reproduce the classical
// steady-sliding curve
// ([Smith2000] eq. 2), so at each speed v of a log grid
//     T_ss(v) = F mu(v) v x ContactHeat::steadyRise(v)     (the steady state of THIS heat model and step)
//     tau_y(T_ss(v)) = F mu(v) / (pi a^2).
// The table stops where T_ss stops rising (it must be invertible). Bowing with the rig's own contact then
// gives a static coefficient 1.2 (a_rig / a_cal)^2 at ambient ([Notes §2.1]: 0.90 on the Galluzzo rig).
//
// Below the calibration's ambient (rosin colder than the rig's stated ambient) the table is extended
// linearly with its mean slope over the first 5 K, capped at +25 %: cold rosin is harder ([Galluzzo2017]
// §5.1).
//
// The same calibration read as a viscosity, for the viscous law ([Smith2000] eq. 3: friction = area x
// eta(T) x slip / layer): at each steady speed eta(T_ss(v)) = tau_y(T_ss(v)) x layer / v, so the viscous law
// slides steadily on the same classical curve. Below the table's slowest speed (1e-7 m/s, its coldest
// point) and for rosin colder than ambient, eta is held at that point's value: a cold contact creeps at
// about 1e-7 m/s, and there is no static friction.
#include <vector>

#include "lab/discovery/independent/ContactHeat.h"

namespace rosin::discovery
{

struct CalibrationContact
{
    double radius = 500e-6;        ///< m
    double normalForce = 3.0;      ///< N
    double layerThickness = 10e-6; ///< m
};

/// [Smith2000] eq. (2): 0.4 e^{-v/0.01} + 0.45 e^{-v/0.1} + 0.35.
double classicalFriction(double speed);

class YieldStressTable
{
  public:
    YieldStressTable(const CalibrationContact& rig, const HeatMaterials& materials, double dt);

    /// tau_y (Pa) at a contact temperature T (K above the calibration's ambient).
    double at(double temperature) const noexcept;
    /// eta (Pa s) at a contact temperature T (K above the calibration's ambient), log-linear in T.
    double viscosity(double temperature) const noexcept;
    const std::vector<double>& temperatures() const noexcept { return temperatures_; }
    const std::vector<double>& speeds() const noexcept { return speeds_; }
    const std::vector<double>& stresses() const noexcept { return stresses_; }

  private:
    std::vector<double> speeds_, temperatures_, stresses_;
    std::vector<double> logViscosities_; ///< ln eta at temperatures_[1..]
    double coldSlope_ = 0.0;             ///< Pa per K below ambient
};

} // namespace rosin::discovery
