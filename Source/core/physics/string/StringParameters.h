#pragma once
// Physical description of one string, in SI units, and the catalogue of strings Rosin ships.
#include <string>
#include <vector>

namespace rosin::physics
{

/// One string as Table 1 of [Galluzzo2017] describes it. Loss coefficients are kept as that table prints
/// them (raw numbers); StringParameters::etaF() etc. apply the scale factors adopted in the physics
/// [Notes §4.1]: eta_F x 1e-5, eta_B x 1e-3, eta_A in 1/s.
struct StringParameters
{
    std::string name;                  ///< e.g. "cello-D3"
    double tension = 111.0;            ///< P, N
    double massPerLength = 2.7e-3;     ///< m, kg/m
    double length = 0.6906;            ///< L, m (open, nut to bridge)
    double bendingStiffness = 3.0e-4;  ///< EI, N m^2
    double lossF = 23.0;               ///< eta_F as printed (x 1e-5)
    double lossB = 12.5;               ///< eta_B as printed (x 1e-3)
    double lossA = 0.11;               ///< eta_A, 1/s
    double stoppedLossF = 69.0;        ///< eta_F when finger-stopped ([Galluzzo2017] Table 1 bracket value)
    double torsionalWaveSpeed = 758.0; ///< c_t, m/s
    double torsionalQ = 45.0;          ///< Q_t
    double torsionalImpedance = 1.8;   ///< Z_t, kg/s, referred to the string surface
    std::string source; ///< where the numbers come from ("[Galluzzo2017] Table 1", "estimate: ...")

    double waveSpeed() const;   ///< c = sqrt(P/m), m/s
    double impedance() const;   ///< Z0 = sqrt(P m), kg/s
    double fundamental() const; ///< f0 = c / (2L) of the open string, Hz (ignoring stiffness)
    double inharmonicity(double vibratingLength) const; ///< B = pi^2 EI / (P L^2)
    double etaF(bool stopped) const { return (stopped ? stoppedLossF : lossF) * 1e-5; }
    double etaB() const { return lossB * 1e-3; }
    double etaA() const { return lossA; }
    /// Loss factor 1/Q of transverse mode n on a string of the given length, [Notes] eq. (4.1).
    double lossFactor(int n, double vibratingLength, bool stopped) const;
    /// Angular frequency of transverse mode n (stiff string, pinned ends), [Notes] eq. (4.2).
    double modeAngularFrequency(int n, double vibratingLength) const;
};

/// Names of the catalogue entries, e.g. "cello-D3", "violin-E5".
std::vector<std::string> stringCatalogueNames();
/// The catalogue entry of that name; throws std::invalid_argument naming the known strings otherwise.
StringParameters stringFromCatalogue(const std::string& name);

} // namespace rosin::physics
