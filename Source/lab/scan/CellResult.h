#pragma once
// What one trial of a scan found: one row of scan.csv (Resources/docs/scan-format.md).
#include <cstddef>
#include <optional>

#include "core/analysis/Regime.h"
#include "core/analysis/TransientLength.h"

namespace rosin::scan
{

struct CellResult
{
    std::size_t cell = 0;
    double beta = 0.0;
    double bowForce = 0.0; ///< N
    double second = 0.0;   ///< acceleration (m/s^2, Guettler) or bow speed (m/s, Schelleng)
    analysis::Regime regime = analysis::Regime::NoSlip; ///< the steady regime at the end of the trial
    /// Periods from the first slip to lasting Helmholtz motion; empty when not reached within the cap.
    std::optional<double> transientPeriods;
    std::optional<double> muStatic;      ///< F_br before the first slip / ((1 - beta) N)
    std::optional<double> jump;          ///< (F_br before - after the first slip) / N
    std::optional<double> firstSlipTime; ///< s from the start of the trial
    std::optional<double> slipsPerPeriod;
    std::optional<double> pitchCents;
    std::optional<analysis::TransientFailure> failure; ///< empty when the string never slipped
};

} // namespace rosin::scan
