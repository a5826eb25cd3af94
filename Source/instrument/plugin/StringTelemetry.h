#pragma once
// Per-string readouts the audio thread publishes for the editor: one std::atomic per field, written once per
// block with relaxed stores and read by the editor's timer. Fields may come from neighbouring blocks (no
// snapshot consistency across fields); for a display that is harmless and keeps both sides wait-free.
#include <array>
#include <atomic>

#include "core/analysis/Regime.h"

namespace rosin::plugin
{

/// What a string is doing: the lab's regimes, judged live by analysis::LiveRegimeMeter.
using analysis::Regime;

/// "Helmholtz", "double slipping", ... for display; "silent" when the bow is not on a moving string.
const char* regimeDisplayName(Regime regime, bool bowing) noexcept;

/// A plain copy of one string's readouts (SI units unless said).
struct StringReadout
{
    float openFrequency = 0.0f;     ///< Hz
    float frequency = 0.0f;         ///< nominal frequency of the sounding note (finger-stopped), Hz
    float temperature = 0.0f;       ///< contact temperature, K above ambient
    float stickFraction = 0.0f;     ///< fraction of the last analysis window spent sticking
    float flybacksPerPeriod = 0.0f; ///< slips with backward string motion per nominal period
    float slipsPerPeriod = 0.0f;    ///< all slip episodes per nominal period
    float irregularity = 0.0f;      ///< coefficient of variation of the flyback intervals
    float bowForce = 0.0f;          ///< N
    float beta = 0.0f;              ///< bow-bridge distance / vibrating length
    float bowVelocity = 0.0f;       ///< m/s
    float impedance = 0.0f;         ///< string wave impedance Z0, kg/s
    float bridgeConductance = 0.0f; ///< mean real bridge admittance plus string losses, s/kg
    float muStatic = 0.0f;          ///< friction law's static coefficient at the current force
    float muSlip = 0.0f;            ///< mean |f| / F_b while slipping (0: no slip in the window)
    float bandMuStatic = 0.0f;      ///< mu_s of the string's playable band (engine::playableBand)
    float bandMuDynamic = 0.0f;     ///< mu_d of the string's playable band
    bool sticking = true;           ///< at the end of the block
    bool bowing = false;            ///< bow on the string and moving
    Regime regime = Regime::NoSlip; ///< meaningful while bowing
};

class StringTelemetry
{
  public:
    /// Audio thread: relaxed atomic stores only.
    void publish(const StringReadout& r) noexcept;
    /// Any thread.
    StringReadout read() const noexcept;

  private:
    enum Field
    {
        kOpenFrequency,
        kFrequency,
        kTemperature,
        kStickFraction,
        kFlybacks,
        kSlips,
        kIrregularity,
        kBowForce,
        kBeta,
        kBowVelocity,
        kImpedance,
        kConductance,
        kMuStatic,
        kMuSlip,
        kBandMuStatic,
        kBandMuDynamic,
        kFieldCount
    };
    std::array<std::atomic<float>, kFieldCount> values_{};
    std::atomic<bool> sticking_{true};
    std::atomic<bool> bowing_{false};
    std::atomic<int> regime_{0};
};

/// Everything the editor reads from the processor.
struct Telemetry
{
    static constexpr int kMaxStrings = 8;
    std::atomic<int> stringCount{0};
    std::array<StringTelemetry, kMaxStrings> strings;
};

} // namespace rosin::plugin
