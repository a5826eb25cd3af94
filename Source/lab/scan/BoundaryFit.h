#pragma once
// The edges of the Helmholtz region of a Schelleng scan, fitted as straight lines on log-log axes
// (log10 F = intercept + slope log10 beta), to compare with Schelleng's F_max ~ 1/beta and F_min ~ 1/beta^2
// ([Notes §6.1-6.2]).
//
// Per beta column: the longest contiguous run of Helmholtz cells along the (ascending) forces (ties: the
// lowest). Its lower edge lies between the force below the run and the run's first force, its upper edge
// between the run's last force and the one above: the geometric mean of the two, the best estimate on a
// log-spaced axis. A run that reaches the grid's first or last force has no edge there (the boundary is
// outside the grid) and the column gives no point for that edge. Only "helmholtz" counts: Schelleng's theory
// is about Helmholtz motion, and S-motion occurs mostly beyond F_max ([Notes §7.4]), so counting it would
// push the upper edge beyond the limit being measured. A fit needs two columns with an edge.
#include <cstddef>
#include <optional>
#include <vector>

#include "lab/scan/CellResult.h"
#include "lab/scan/ScanSpec.h"

namespace rosin::scan
{

struct LineFit
{
    double slope = 0.0;
    double intercept = 0.0;
    std::size_t points = 0;
};

struct BoundaryPoint
{
    double beta = 0.0;
    double force = 0.0; ///< N
};

struct HelmholtzEdges
{
    std::vector<BoundaryPoint> upper, lower;
};

/// The edge points of every beta column (results indexed by cell; one bow speed).
HelmholtzEdges helmholtzEdges(const ScanSpec& spec, const std::vector<CellResult>& results);
/// Least squares of log10 force on log10 beta; empty with fewer than two points (or all at one beta).
std::optional<LineFit> fitLogLog(const std::vector<BoundaryPoint>& points);

} // namespace rosin::scan
