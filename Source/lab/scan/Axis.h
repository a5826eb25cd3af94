#pragma once
// The values along one axis of a scan grid: linearly spaced (Guettler's N-a plane, [Galluzzo2017]
// section 3.2) or logarithmically spaced (Schelleng's beta and force, section 3.1), ends included.
#include <cstddef>
#include <vector>

namespace rosin::scan
{

/// n values from first to last, equally spaced; n == 1 gives {first}.
std::vector<double> linearAxis(double first, double last, std::size_t n);
/// n values from first to last (both > 0), equally spaced in log; n == 1 gives {first}.
std::vector<double> logAxis(double first, double last, std::size_t n);

} // namespace rosin::scan
