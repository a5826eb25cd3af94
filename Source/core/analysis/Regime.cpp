#include "core/analysis/Regime.h"

namespace rosin::analysis
{

const char* regimeName(Regime regime) noexcept
{
    switch (regime)
    {
    case Regime::Helmholtz:
        return "helmholtz";
    case Regime::SMotion:
        return "s-motion";
    case Regime::DoubleSlipping:
        return "double-slipping";
    case Regime::MultipleSlipping:
        return "multiple-slipping";
    case Regime::Raucous:
        return "raucous";
    case Regime::AnomalousLowFrequency:
        return "alf";
    case Regime::ConstantSlipping:
        return "constant-slipping";
    case Regime::NoSlip:
        return "no-slip";
    }
    return "no-slip";
}

std::vector<Regime> allRegimes()
{
    return {Regime::Helmholtz,        Regime::SMotion, Regime::DoubleSlipping,
            Regime::MultipleSlipping, Regime::Raucous, Regime::AnomalousLowFrequency,
            Regime::ConstantSlipping, Regime::NoSlip};
}

std::optional<Regime> parseRegime(std::string_view name) noexcept
{
    for (const Regime r :
         {Regime::Helmholtz, Regime::SMotion, Regime::DoubleSlipping, Regime::MultipleSlipping,
          Regime::Raucous, Regime::AnomalousLowFrequency, Regime::ConstantSlipping, Regime::NoSlip})
        if (name == regimeName(r))
            return r;
    // The plugin's live detector calls a string that never slips "silent".
    if (name == "silent")
        return Regime::NoSlip;
    return std::nullopt;
}

} // namespace rosin::analysis
