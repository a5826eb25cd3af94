#pragma once
// The ribbon's force while it slides is not smooth: of the hairs that touch the string, each catches and
// releases on its own, so the force the ribbon slides with fluctuates about the friction law's mu F_b. Heard
// as the bow noise that comes in pulses, once per slip ([Chafe1990]: pulsed noise in self-sustained
// oscillations; [Euphonics] 9.7, differential slipping). Modelled as a zero-mean Gaussian
// fluctuation of the force the law is given, drawn afresh each sample while the contact slides (the voice
// asks only while the string flies back) and not at all while it sticks, so a held string stays held.
#include <cstdint>
#include <random>

namespace rosin::physics
{

class SlipNoise
{
  public:
    /// Off the audio thread. `relativeRms`: the fluctuation's rms against the force, as seen at 48 kHz (its
    /// spectral density is kept at other rates: the per-sample rms grows as sqrt(rate / 48 kHz)). `seed`
    /// picks the stream, so that each string draws its own and a render repeats.
    void prepare(double relativeRms, double sampleRate, std::uint64_t seed);
    /// Back to the start of the stream. Real-time safe.
    void reset() noexcept;
    /// The factor on this sample's bow force: 1 while sticking (or without noise), else 1 + the fluctuation
    /// (never below 0). Real-time safe.
    double forceFactor(bool sliding) noexcept;
    bool active() const noexcept { return perSampleRms_ > 0.0; }

  private:
    double perSampleRms_ = 0.0;
    std::uint64_t seed_ = 0;
    std::mt19937_64 engine_;
    std::normal_distribution<double> normal_;
};

} // namespace rosin::physics
