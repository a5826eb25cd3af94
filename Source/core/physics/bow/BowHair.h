#pragma once
// The bow hair's give in the bowing direction: a spring k_h and a dashpot r_h in parallel between the bow
// stick (moving at v_b) and the contact, massless. With x the contact's displacement from the stick and f the
// friction force on the string (so -f on the hair), -f = k_h x + r_h x'. Trapezoidal in time (passive at
// every frequency, as the bilinear map keeps a positive-real admittance positive-real):
//     x'[n] = h - y_h f[n],   y_h = 1 / (r_h + k_h T / 2),   h = -(k_h x[n-1] + (k_h T / 2) x'[n-1]) y_h,
// so the hair adds y_h to the bow port's instantaneous admittance and h to its history: the friction law
// solves dv = v_string - v_hair on the same kind of load line as without hair. Rigid hair: y_h = 0, h = 0.
namespace rosin::physics
{

struct BowParameters;

/// The hair's coefficients at one sample rate.
struct HairTerms
{
    double admittance = 0.0; ///< y_h, s/kg (0: rigid hair)
    double stiffness = 0.0;  ///< k_h, N/m
    double halfStep = 0.0;   ///< T / 2, s
};

/// The hair's state: the contact's displacement from the stick (m) and its velocity (m/s) at the last sample.
struct HairState
{
    double x = 0.0, xd = 0.0;
};

HairTerms hairTerms(const BowParameters& bow, double sampleRate) noexcept;

/// h: the contact's velocity relative to the stick this sample if the friction force were zero, m/s.
inline double hairHistory(const HairTerms& t, const HairState& s) noexcept
{
    return -(t.stiffness * s.x + t.stiffness * t.halfStep * s.xd) * t.admittance;
}

/// The sample's contact velocity relative to the stick under friction force f, with its history h; advances
/// the state. Returns x'[n].
inline double advanceHair(const HairTerms& t, HairState& s, double h, double f) noexcept
{
    const double xd = h - t.admittance * f;
    s.x += t.halfStep * (xd + s.xd);
    s.xd = xd;
    return xd;
}

} // namespace rosin::physics
