#pragma once
// Guettler's wedge of clean starts from rest ([Guettler2002], [Notes §6] eq. 6.6): a constant bow
// acceleration a gives Helmholtz motion from the first slip when a_low < a <= a_up, each proportional to the
// bow force F:
//   a_low = beta (1 - beta) F [3 mu_s - mu_d - 2 sqrt(2 mu_s^2 - mu_s mu_d)] / (P Z0)
//   a_up  = beta (1 - beta) F [(3 - 4 beta) mu_s - mu_d - 2 sqrt((1 - 2 beta)(2 (1 - beta) mu_s^2 - mu_s
//   mu_d))]
//           / ((1 - 2 beta) P Z0)
// with P Z0 = twice the vibrating string's mass. A reference: the model's own wedge differs ([Notes §6]).

namespace rosin::physics
{

struct GuettlerWedge
{
    double beta = 0.0;
    double lowerAccelerationPerNewton = 0.0; ///< m/s^2 per N
    double upperAccelerationPerNewton = 0.0; ///< m/s^2 per N
};

/// The wedge at beta (0 < beta < 0.5) for mu_s, mu_d and P Z0 (kg).
GuettlerWedge guettlerWedge(double beta, double muStatic, double muDynamic, double periodTimesZ0) noexcept;

} // namespace rosin::physics
