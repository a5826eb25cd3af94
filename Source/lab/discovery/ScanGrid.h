#pragma once
// The grid a dataset's trials lie on, found from the trials themselves: the spec promises neither a complete
// nor a regular grid. A Guettler scan is beta x bowForce x acceleration (constant-acceleration trials), a
// Schelleng scan beta x bowForce x speed (steady trials). Only valid trials count; invalid ones are tallied.
#include <cstddef>
#include <string>
#include <vector>

#include "lab/discovery/Dataset.h"

namespace rosin::discovery
{

enum class ScanKind
{
    Empty,     ///< no valid trial
    Guettler,  ///< every valid trial is constant-acceleration
    Schelleng, ///< every valid trial is steady
    Recorded,  ///< every valid trial is recorded: no motion axis
    Mixed,     ///< gestures of more than one type: no motion axis
};

std::string scanKindName(ScanKind kind);

/// One occupied point of the grid: indices into the axes and the dataset indices of its trials (repeats
/// share a cell).
struct GridCell
{
    std::size_t beta = 0, force = 0, motion = 0;
    std::vector<std::size_t> trials;
};

struct ScanGrid
{
    ScanKind kind = ScanKind::Empty;
    std::vector<double> betas;  ///< distinct, ascending
    std::vector<double> forces; ///< distinct, ascending, N
    /// Accelerations (Guettler, m/s^2) or speeds (Schelleng, m/s), distinct, ascending; empty for the other
    /// kinds, whose cells then all have motion index 0.
    std::vector<double> motion;
    std::vector<GridCell> cells; ///< the occupied cells, ordered by beta, force, motion
    std::size_t validTrials = 0;
    std::size_t invalidTrials = 0;

    /// betas x forces x motion values (a missing motion axis counts as one value).
    std::size_t possibleCells() const;
    /// The cells of the full product that no valid trial occupies, in the same order as `cells`.
    std::vector<GridCell> missingCells() const;
    /// The occupied cell at those values (matched as the axes were built), or nullptr.
    const GridCell* find(double beta, double force, double motionValue = 0.0) const;
    /// "Guettler scan: 3 betas x 4 forces x 3 accelerations, 35 of 36 cells, 1 invalid trial".
    std::string summary() const;
};

/// Values closer than this (relative) are one grid value: lab scripts may print 0.84 as 0.84000000000000008.
inline constexpr double kGridTolerance = 1e-9;

ScanGrid findScanGrid(const std::vector<Trial>& trials);
inline ScanGrid findScanGrid(const Dataset& dataset)
{
    return findScanGrid(dataset.trials);
}

} // namespace rosin::discovery
