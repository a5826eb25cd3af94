#pragma once
// The steady-state regimes of a bowed string that the playability lab tells apart ([Notes §7.4]),
// with stable short names for CSV files and plots.
#include <optional>
#include <string_view>
#include <vector>

namespace rosin::analysis
{

enum class Regime
{
    Helmholtz,             ///< one slip per period P, sawtooth bridge force
    SMotion,               ///< one slip per period, but a strong secondary corner (sawtoothness off 1)
    DoubleSlipping,        ///< two slips per period, period still P ("surface sound", below F_min)
    MultipleSlipping,      ///< three or more slips per period
    Raucous,               ///< no stable period (above F_max, "crunch")
    AnomalousLowFrequency, ///< periodic with a period >= 1.1 P (up to an octave and more below the note)
    ConstantSlipping,      ///< the string slides throughout: no sticking after the transient
    NoSlip                 ///< the bow sticks throughout: no slip at all (silent)
};

/// "helmholtz", "s-motion", "double-slipping", "multiple-slipping", "raucous", "alf", "constant-slipping",
/// "no-slip". Stable: CSV files written by the lab use them.
const char* regimeName(Regime regime) noexcept;
/// Every regime, in declaration order.
std::vector<Regime> allRegimes();
/// Inverse of regimeName (exact, lower case); "silent" is accepted for NoSlip. Empty for anything else.
std::optional<Regime> parseRegime(std::string_view name) noexcept;

} // namespace rosin::analysis
