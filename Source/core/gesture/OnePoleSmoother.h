#pragma once
// One-pole low-pass for control signals, y[n] = y[n-1] + k (x[n] - y[n-1]), k = 1 - exp(-1 / (tau fs)).
// After a step the remaining error is exp(-t / tau): 99.3 % of the step is covered within 5 tau.
// The first value after reset() is taken as is (snap), never approached from zero: a gesture that starts
// at 1 N must start at 1 N, or the smoother itself would shape the pre-slip transient being simulated.
#include <cmath>

namespace rosin::gesture
{

class OnePoleSmoother
{
  public:
    /// Off the audio thread (uses exp). timeConstantSeconds <= 0 disables smoothing.
    void prepare(double timeConstantSeconds, double sampleRate)
    {
        coefficient_ =
            timeConstantSeconds > 0.0 ? 1.0 - std::exp(-1.0 / (timeConstantSeconds * sampleRate)) : 1.0;
        reset();
    }
    /// The next process() call snaps to its input.
    void reset() noexcept { primed_ = false; }
    /// Jump to `value` without smoothing (the next process() continues from here).
    void snapTo(double value) noexcept
    {
        value_ = value;
        primed_ = true;
    }
    double process(double target) noexcept
    {
        if (!primed_)
            snapTo(target);
        else
            value_ += coefficient_ * (target - value_);
        return value_;
    }
    double value() const noexcept { return value_; }
    double coefficient() const noexcept { return coefficient_; }

  private:
    double coefficient_ = 1.0;
    double value_ = 0.0;
    bool primed_ = false;
};

} // namespace rosin::gesture
