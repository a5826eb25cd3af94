#pragma once
// [Smith2000]'s stick-slip rig: one damped mode  m x'' + R x' + S x = f(t)  ([Smith2000] eq. 1), the first
// bending mode of a cantilever at the contact point, "bowed" by a rosin-coated rod.
#include <string>

namespace rosin::physics
{

struct OscillatorRigParameters
{
    double frequency = 108.0;    ///< f0 = sqrt(S/m) / 2 pi, Hz ([Smith2000]: first bending mode)
    double qualityFactor = 20.0; ///< Q = m omega0 / R ([Smith2000]: Q 20 for the first two bending modes)
    /// m, kg. Not in [Smith2000]: chosen so that the traditional curve ([Smith2000] eq. 2) gives stick-slip
    /// at 34 Hz with N = 6.3 N and v_rod = 0.042 m/s, as [Smith2000] reports. Found by bisection
    /// (calibrateModalMass, RigCalibration.h; reproduced by
    /// tests/core/physics/rig/TraditionalCurveRigTest.cpp).
    double modalMass = 0.0216;

    double angularFrequency() const; ///< omega0, rad/s
    double stiffness() const;        ///< S = m omega0^2, N/m
    double resistance() const;       ///< R = m omega0 / Q, kg/s
    /// Throws std::invalid_argument naming the field and the expected range.
    void validate() const;
};

/// [Smith2000]'s normal load and rod speed (Fig. 2, the case simulated in Figs. 3-5).
struct CantileverLoad
{
    static constexpr double normalForce = 6.3; ///< N
    static constexpr double rodSpeed = 0.042;  ///< m/s
};

} // namespace rosin::physics
