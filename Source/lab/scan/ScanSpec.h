#pragma once
// Everything that decides a scan's results: the kind of diagram, the model, the trial protocol and the grid.
// Nothing about how the work is split (threads, shards, ranks) belongs here: the same spec gives the same
// files however it is computed.
//
// Cells are numbered in grid order (Resources/docs/scan-format.md):
//   cell = (iBeta * nForce + iForce) * nSecond + iSecond,
// where the second axis is the acceleration (Guettler) or the bow speed (Schelleng, one value, so
// cell = iBeta * nForce + iForce).
#include <cstddef>
#include <vector>

#include "lab/scan/ModelSpec.h"

namespace rosin::scan
{

enum class ScanKind
{
    Schelleng, ///< steady bowing at one speed over (beta, force), log-spaced: the regime at the end
    Guettler   ///< constant-acceleration starts over (force, acceleration) at each beta: the transient
};

/// "schelleng" / "guettler".
const char* kindName(ScanKind kind) noexcept;

/// Where a Guettler trial ends (its first slip and transient come out the same with every rule; TrialEnd.h).
enum class GuettlerTrialEnd
{
    Whole,       ///< all trialSeconds
    AfterWindow, ///< once the transient window is over: 2 x cap periods (+10 %) after the first flyback
    WhenDecided  ///< as AfterWindow, or sooner once the transient can no longer start within the cap
};
/// "whole", "window", "decided".
const char* trialEndName(GuettlerTrialEnd end) noexcept;

/// How a trial's slips are found for its regime and transient (CellAnalysis.h).
enum class Classification
{
    State,      ///< from the solver's sticking state and bow-point velocity (full flybacks)
    BridgeForce ///< from the bridge force alone, as [Galluzzo2017] treats measured and simulated trials alike
};
/// "state", "bridge-force".
const char* classificationName(Classification c) noexcept;

struct ScanSpec
{
    ScanKind kind = ScanKind::Guettler;
    ModelSpec model;
    double sampleRate = 48000.0; ///< Hz
    double trialSeconds = 0.5;   ///< s, length of every trial
    /// Schelleng: the bow reaches its speed with constant acceleration over this time (s); unused (0) for
    /// Guettler, whose bow accelerates for the whole trial.
    double rampSeconds = 0.0;
    /// Guettler: where each trial ends (TrialEnd.h). WhenDecided by default; Whole with `--full-trials`.
    GuettlerTrialEnd trialEnd = GuettlerTrialEnd::WhenDecided;
    /// How slips are found. BridgeForce trials end at the latest with their transient window (the "decided"
    /// rule follows the solver's flybacks, which the bridge force need not agree with).
    Classification classification = Classification::State;
    std::vector<double> betas;
    std::vector<double> forces; ///< N
    std::vector<double> second; ///< accelerations, m/s^2 (Guettler), or bow speeds, m/s (Schelleng)

    std::size_t cellCount() const noexcept { return betas.size() * forces.size() * second.size(); }
};

/// [Galluzzo2017]'s grids (section 3): Schelleng 20 x 20, force 0.1-3 N and beta 0.02-0.18 log-spaced, bow
/// speed 0.05 m/s, 1 s trials with a 0.1 s ramp; Guettler 20 x 20, force 0.4-3.2 N and acceleration 0.08-3.2
/// m/s^2 linearly spaced at the eight betas of Fig. 5, 0.5 s trials. Model: the galluzzo-rig preset.
ScanSpec defaultSpec(ScanKind kind);

/// The eight bow positions of [Galluzzo2017] Fig. 5.
const std::vector<double>& seedGuettlerBetas();

/// Indices of a cell along the three axes.
struct CellCoordinates
{
    std::size_t beta = 0, force = 0, second = 0;
};

/// A cell's nominal settings.
struct CellSettings
{
    std::size_t cell = 0;
    double beta = 0.0;
    double force = 0.0;  ///< N
    double second = 0.0; ///< acceleration (m/s^2) or bow speed (m/s)
};

CellCoordinates coordinatesOf(const ScanSpec& spec, std::size_t cell);
std::size_t cellIndex(const ScanSpec& spec, const CellCoordinates& c);
CellSettings cellSettings(const ScanSpec& spec, std::size_t cell);

} // namespace rosin::scan
