#include "instrument/plugin/StringTelemetry.h"

namespace rosin::plugin
{

const char* regimeDisplayName(Regime regime, bool bowing) noexcept
{
    if (!bowing)
        return "silent";
    switch (regime)
    {
    case Regime::Helmholtz:
        return "Helmholtz";
    case Regime::SMotion:
        return "S-motion";
    case Regime::DoubleSlipping:
        return "double slipping";
    case Regime::MultipleSlipping:
        return "multiple slipping";
    case Regime::Raucous:
        return "raucous";
    case Regime::AnomalousLowFrequency:
        return "low (ALF)";
    case Regime::ConstantSlipping:
        return "sliding";
    case Regime::NoSlip:
        break;
    }
    return "stuck";
}

void StringTelemetry::publish(const StringReadout& r) noexcept
{
    constexpr auto relaxed = std::memory_order_relaxed;
    values_[kOpenFrequency].store(r.openFrequency, relaxed);
    values_[kFrequency].store(r.frequency, relaxed);
    values_[kTemperature].store(r.temperature, relaxed);
    values_[kStickFraction].store(r.stickFraction, relaxed);
    values_[kFlybacks].store(r.flybacksPerPeriod, relaxed);
    values_[kSlips].store(r.slipsPerPeriod, relaxed);
    values_[kIrregularity].store(r.irregularity, relaxed);
    values_[kBowForce].store(r.bowForce, relaxed);
    values_[kBeta].store(r.beta, relaxed);
    values_[kBowVelocity].store(r.bowVelocity, relaxed);
    values_[kImpedance].store(r.impedance, relaxed);
    values_[kConductance].store(r.bridgeConductance, relaxed);
    values_[kMuStatic].store(r.muStatic, relaxed);
    values_[kMuSlip].store(r.muSlip, relaxed);
    values_[kBandMuStatic].store(r.bandMuStatic, relaxed);
    values_[kBandMuDynamic].store(r.bandMuDynamic, relaxed);
    sticking_.store(r.sticking, relaxed);
    bowing_.store(r.bowing, relaxed);
    regime_.store(static_cast<int>(r.regime), relaxed);
}

StringReadout StringTelemetry::read() const noexcept
{
    constexpr auto relaxed = std::memory_order_relaxed;
    StringReadout r;
    r.openFrequency = values_[kOpenFrequency].load(relaxed);
    r.frequency = values_[kFrequency].load(relaxed);
    r.temperature = values_[kTemperature].load(relaxed);
    r.stickFraction = values_[kStickFraction].load(relaxed);
    r.flybacksPerPeriod = values_[kFlybacks].load(relaxed);
    r.slipsPerPeriod = values_[kSlips].load(relaxed);
    r.irregularity = values_[kIrregularity].load(relaxed);
    r.bowForce = values_[kBowForce].load(relaxed);
    r.beta = values_[kBeta].load(relaxed);
    r.bowVelocity = values_[kBowVelocity].load(relaxed);
    r.impedance = values_[kImpedance].load(relaxed);
    r.bridgeConductance = values_[kConductance].load(relaxed);
    r.muStatic = values_[kMuStatic].load(relaxed);
    r.muSlip = values_[kMuSlip].load(relaxed);
    r.bandMuStatic = values_[kBandMuStatic].load(relaxed);
    r.bandMuDynamic = values_[kBandMuDynamic].load(relaxed);
    r.sticking = sticking_.load(relaxed);
    r.bowing = bowing_.load(relaxed);
    const int regime = regime_.load(relaxed);
    r.regime = regime >= 0 && regime <= static_cast<int>(Regime::NoSlip) ? static_cast<Regime>(regime)
                                                                         : Regime::NoSlip;
    return r;
}

} // namespace rosin::plugin
