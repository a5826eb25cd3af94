#pragma once
// A delay line read at a fractional delay, for the travelling waves of the independent generator's waveguide
// string. Samples are kept by absolute step index (write(n, x) stores x[n]); read(n, D) returns x[n - D]
// interpolated by a cubic Lagrange polynomial (flat group delay at low frequency, so a string's pitch is set
// by D alone), or linearly when D is below 2 samples and the cubic's taps would reach the future.
#include <cmath>
#include <cstddef>
#include <vector>

namespace rosin::discovery
{

class FractionalDelay
{
  public:
    /// Room for delays up to maxDelay samples.
    explicit FractionalDelay(double maxDelay = 4.0)
    {
        std::size_t size = 8;
        while (size < static_cast<std::size_t>(maxDelay) + 8)
            size *= 2;
        buffer_.assign(size, 0.0);
        mask_ = size - 1;
    }

    void write(std::size_t n, double x) noexcept { buffer_[n & mask_] = x; }

    /// x[n - delay], delay >= 1 (>= 0 if x[n] has been written); samples before the start read 0.
    double read(std::size_t n, double delay) const noexcept
    {
        const double whole = std::floor(delay);
        const double d = delay - whole;
        const auto i = static_cast<std::ptrdiff_t>(n) - static_cast<std::ptrdiff_t>(whole);
        if (whole < 2.0) // linear: x[i] and x[i - 1]
            return (1.0 - d) * at(i) + d * at(i - 1);
        // Taps at delays whole - 1 .. whole + 2, i.e. indices i + 1 .. i - 2 (reference point i, fraction d).
        const double hm1 = -d * (d - 1.0) * (d - 2.0) / 6.0;
        const double h0 = (d + 1.0) * (d - 1.0) * (d - 2.0) / 2.0;
        const double h1 = -(d + 1.0) * d * (d - 2.0) / 2.0;
        const double h2 = (d + 1.0) * d * (d - 1.0) / 6.0;
        return hm1 * at(i + 1) + h0 * at(i) + h1 * at(i - 1) + h2 * at(i - 2);
    }

  private:
    double at(std::ptrdiff_t i) const noexcept
    {
        return i < 0 ? 0.0 : buffer_[static_cast<std::size_t>(i) & mask_];
    }
    std::vector<double> buffer_;
    std::size_t mask_ = 0;
};

} // namespace rosin::discovery
