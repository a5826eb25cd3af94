#pragma once
// The ribbon's geometry in modal terms. A friction force f spread evenly over a width W centred on the bow
// point x_b = beta L drives mode n through the mean of its shape over the ribbon,
//     phi_n = (1/W) int sin(n pi x / L) dx = sin(n pi beta) sinc(n pi W / (2 L)),
// and the velocity the friction law sees is the same mean over the ribbon, so the bow port stays reciprocal
// and the power f dv is what the whole contact dissipates. A mode whose shape averages out over the ribbon
// is not bowed at all: the ribbon is a spatial low-pass on the string's coupling to the bow, which rounds
// the Helmholtz corner over the time it takes to cross the ribbon, W / c.
namespace rosin::physics
{

/// The width the ribbon can have on a string of vibrating length L bowed at beta: no wider than twice the
/// distance to the bridge (hair beyond the bridge touches no string), m.
double ribbonWidthOnString(double width, double beta, double length) noexcept;

/// sinc(n pi W / (2 L)): mode n's coupling to an even ribbon of width W relative to a point bow (1 at W = 0).
double ribbonModeFactor(int n, double width, double length) noexcept;

/// Share of a point force's instantaneous answer 1/(2Z) that the mean velocity over a ribbon keeps within
/// one sample of length T, for waves of speed c: the ribbon-mean response to an impulse spread over it is
/// the triangle (c / (Z W)) (1 - c t / W), t < W / c, whose integral over the first half sample is
/// (2u - u^2) / (2Z), u = c T / (2 W) (1 once the ribbon is crossed within the half sample).
double ribbonDirectShare(double waveSpeed, double samplePeriod, double width) noexcept;

} // namespace rosin::physics
