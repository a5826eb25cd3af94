#include "lab/discovery/ScanGrid.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <tuple>

namespace rosin::discovery
{

namespace
{
bool same(double a, double b)
{
    return std::abs(a - b) <= kGridTolerance * std::max(std::abs(a), std::abs(b));
}

// Sorted distinct values, near-equal ones merged into the first seen after sorting.
std::vector<double> distinct(std::vector<double> values)
{
    std::sort(values.begin(), values.end());
    std::vector<double> out;
    for (double v : values)
        if (out.empty() || !same(out.back(), v))
            out.push_back(v);
    return out;
}

std::optional<std::size_t> indexOf(const std::vector<double>& axis, double value)
{
    for (std::size_t i = 0; i < axis.size(); ++i)
        if (same(axis[i], value))
            return i;
    return std::nullopt;
}

std::optional<double> motionOf(const Gesture& gesture)
{
    if (const auto* a = std::get_if<ConstantAcceleration>(&gesture))
        return a->acceleration;
    if (const auto* s = std::get_if<Steady>(&gesture))
        return s->speed;
    return std::nullopt;
}

ScanKind kindOf(const std::vector<Trial>& trials)
{
    std::optional<std::size_t> type;
    for (const auto& t : trials)
    {
        if (!t.valid)
            continue;
        if (type && *type != t.gesture.index())
            return ScanKind::Mixed;
        type = t.gesture.index();
    }
    if (!type)
        return ScanKind::Empty;
    // In the order of the Gesture variant.
    const ScanKind byType[] = {ScanKind::Guettler, ScanKind::Schelleng, ScanKind::Recorded};
    return byType[*type];
}

bool cellOrder(const GridCell& a, const GridCell& b)
{
    return std::tie(a.beta, a.force, a.motion) < std::tie(b.beta, b.force, b.motion);
}

std::string plural(std::size_t n, const std::string& word)
{
    return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}
} // namespace

std::string scanKindName(ScanKind kind)
{
    switch (kind)
    {
    case ScanKind::Guettler:
        return "Guettler";
    case ScanKind::Schelleng:
        return "Schelleng";
    case ScanKind::Recorded:
        return "recorded";
    case ScanKind::Mixed:
        return "mixed";
    default:
        return "empty";
    }
}

ScanGrid findScanGrid(const std::vector<Trial>& trials)
{
    ScanGrid grid;
    grid.kind = kindOf(trials);
    const bool hasMotion = grid.kind == ScanKind::Guettler || grid.kind == ScanKind::Schelleng;
    std::vector<double> betas, forces, motion;
    for (const auto& t : trials)
    {
        if (!t.valid)
        {
            ++grid.invalidTrials;
            continue;
        }
        ++grid.validTrials;
        betas.push_back(t.beta);
        forces.push_back(t.bowForce);
        if (hasMotion)
            motion.push_back(*motionOf(t.gesture));
    }
    grid.betas = distinct(betas);
    grid.forces = distinct(forces);
    grid.motion = distinct(motion);

    for (std::size_t i = 0; i < trials.size(); ++i)
    {
        const Trial& t = trials[i];
        if (!t.valid)
            continue;
        GridCell key{*indexOf(grid.betas, t.beta),
                     *indexOf(grid.forces, t.bowForce),
                     hasMotion ? *indexOf(grid.motion, *motionOf(t.gesture)) : 0,
                     {}};
        auto it = std::lower_bound(grid.cells.begin(), grid.cells.end(), key, cellOrder);
        if (it == grid.cells.end() || cellOrder(key, *it))
            it = grid.cells.insert(it, key);
        it->trials.push_back(i);
    }
    return grid;
}

std::size_t ScanGrid::possibleCells() const
{
    return betas.size() * forces.size() * std::max<std::size_t>(1, motion.size());
}

std::vector<GridCell> ScanGrid::missingCells() const
{
    std::vector<GridCell> missing;
    if (kind == ScanKind::Empty)
        return missing;
    const std::size_t motionCount = std::max<std::size_t>(1, motion.size());
    auto occupied = cells.begin();
    for (std::size_t b = 0; b < betas.size(); ++b)
        for (std::size_t f = 0; f < forces.size(); ++f)
            for (std::size_t m = 0; m < motionCount; ++m)
            {
                const GridCell cell{b, f, m, {}};
                if (occupied != cells.end() && !cellOrder(cell, *occupied))
                    ++occupied; // both ordered alike: equal means occupied
                else
                    missing.push_back(cell);
            }
    return missing;
}

const GridCell* ScanGrid::find(double beta, double force, double motionValue) const
{
    const auto b = indexOf(betas, beta), f = indexOf(forces, force);
    const auto m = motion.empty() ? std::optional<std::size_t>(0) : indexOf(motion, motionValue);
    if (!b || !f || !m)
        return nullptr;
    for (const auto& cell : cells)
        if (cell.beta == *b && cell.force == *f && cell.motion == *m)
            return &cell;
    return nullptr;
}

std::string ScanGrid::summary() const
{
    std::string text = scanKindName(kind) + " scan: " + plural(betas.size(), "beta") + " x " +
                       plural(forces.size(), "force");
    if (kind == ScanKind::Guettler)
        text += " x " + plural(motion.size(), "acceleration");
    else if (kind == ScanKind::Schelleng)
        text += " x " + plural(motion.size(), "speed");
    text += ", " + std::to_string(cells.size()) + " of " + std::to_string(possibleCells()) + " cells, " +
            plural(invalidTrials, "invalid trial");
    return text;
}

} // namespace rosin::discovery
