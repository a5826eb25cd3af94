#include "core/physics/body/BodyParameters.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

#include "core/physics/body/BodyRadiation.h"

// Body = a few parametric low "signature" modes ([Notes §5.2]) + a statistical set above a crossover
// ([Notes §5.3]). Every number below is an engineering estimate [A]/[M] unless tagged otherwise: no
// verified cello or violin modal table was available ([Notes §10] Q5). Replace with fitted data when
// possible.

namespace rosin::physics
{
namespace
{
constexpr double twoPi = 2.0 * std::numbers::pi;

/// Statistical high-frequency body ([Notes §5.3] items 1-6).
struct StatisticalRecipe
{
    double crossoverHz;       ///< first statistical mode lies above this
    double modalDensityPerHz; ///< n_f, modes per Hz (constant: plate modal density is frequency independent)
    double skeletonRealY;     ///< Re Y_skel below the bridge hill, s/kg
    double hillFrequencyHz;   ///< bridge-hill centre (bridge rocking resonance on the body)
    double hillQ;             ///< bridge-hill quality factor; peak of Re Y_skel is hillQ^2 * skeletonRealY
    double lossAt1kHz;        ///< loss factor eta at 1 kHz
    double lossExponent;      ///< eta(f) = lossAt1kHz * (f / 1 kHz)^lossExponent: the "mild rise"
    double denseLimitHz;      ///< above this, one band mode per 1/12 octave stands for the overlapping modes
};

/// Portable random draws. std::mt19937's output sequence is fixed by the standard, but the standard
/// distributions are not, so the transforms are written out here. Results agree across platforms up to the
/// last-bit rounding of the libm functions used (log, cos, pow), i.e. to ~1e-15 relative.
class PortableRandom
{
  public:
    explicit PortableRandom(std::uint32_t seed) : gen_(seed) {}
    /// Uniform on the open interval (0, 1): never 0, so log() is safe.
    double uniform() { return (static_cast<double>(gen_()) + 0.5) / 4294967296.0; }
    /// Unit-variance Gaussian by Box-Muller (cosine branch only, so each call uses exactly two draws).
    double gaussian()
    {
        const double r = std::sqrt(-2.0 * std::log(uniform()));
        return r * std::cos(twoPi * uniform());
    }
    /// Wigner (GOE) spacing with unit mean, p(s) = (pi s / 2) exp(-pi s^2 / 4), by inverse CDF:
    /// CDF = 1 - exp(-pi s^2 / 4)  =>  s = sqrt(-4 ln(1 - u) / pi); 1 - u is also uniform on (0, 1).
    double wignerSpacing() { return std::sqrt(-4.0 * std::log(uniform()) / std::numbers::pi); }

  private:
    std::mt19937 gen_;
};

/// Re Y_skel(f), s/kg: the plate skeleton level shaped by the single-resonator bridge-hill model of reference
/// §5.3 item 5 (Y_b = (i w + k Y_v) / (k - w^2 m + i w m k Y_v), EUPH 5.3.1 eq. 6 [V2]). With a real Y_v its
/// real part is exactly Y_v / ((1 - x^2)^2 + x^2 / Q_h^2), x = f / f_h, Q_h = 1 / (w_h m Y_v) [D]: flat below
/// the hill, Q_h^2 Y_v at it, and falling as f^-4 above it where the bridge mass takes over.
double skeletonRealAdmittance(const StatisticalRecipe& r, double frequencyHz)
{
    const double x = frequencyHz / r.hillFrequencyHz;
    const double a = 1.0 - x * x;
    return r.skeletonRealY / (a * a + x * x / (r.hillQ * r.hillQ));
}

/// Above a few times the crossover the modal overlap eta f n_f exceeds 1 and the real admittance is a smooth
/// skeleton; simulating every mode there costs time and adds nothing the ear or the string can resolve.
/// One mode per 1/12 octave (spacing df = 5.9 % of f) carries the mean admittance of the modes it replaces
/// (1/m = 4 Re Y_skel df, the same rule as <1/m> above with n_f = 1/df), damped so that neighbouring band
/// modes overlap (eta >= df/f): a smooth skeleton with about 40 modes from 1 to 10 kHz instead of 600.
void appendBandModes(std::vector<BodyMode>& modes, const StatisticalRecipe& r, double fromHz,
                     double maxFrequencyHz)
{
    const double step = std::pow(2.0, 1.0 / 12.0);
    for (double f = fromHz * std::sqrt(step); f < maxFrequencyHz; f *= step)
    {
        const double df = f * (std::sqrt(step) - 1.0 / std::sqrt(step));
        const double eta = std::max(r.lossAt1kHz * std::pow(f / 1000.0, r.lossExponent), df / f);
        modes.push_back({f, 1.0 / eta, 1.0 / (4.0 * skeletonRealAdmittance(r, f) * df)});
    }
}

/// Appends GOE-spaced modes from the crossover up to maxFrequencyHz (exclusive).
void appendStatisticalModes(std::vector<BodyMode>& modes, const StatisticalRecipe& r, std::uint32_t seed,
                            double maxFrequencyHz)
{
    PortableRandom rng(seed);
    const double meanSpacingHz = 1.0 / r.modalDensityPerHz;
    double f = r.crossoverHz;
    // Fixed draw order per mode (spacing, then two uniforms for the amplitude), so a body generated to a
    // lower maxFrequencyHz is an exact prefix of a wider one with the same seed.
    for (;;)
    {
        f += meanSpacingHz * rng.wignerSpacing();
        const double g = rng.gaussian();
        if (f >= maxFrequencyHz)
            break;
        // [Notes §5.3] item 4: <1/m> = 2 Re Y_skel / (pi n_w), n_w = n_f / (2 pi)  =>  <1/m> = 4 Re Y_skel
        // / n_f. Each mode's Re Y integrates to pi / (2 m) over omega, so this reproduces the skeleton on
        // average.
        const double meanInverseMass = 4.0 * skeletonRealAdmittance(r, f) / r.modalDensityPerHz;
        // Porter-Thomas: the mode shape at the bridge is Gaussian, so 1/m ~ chi^2_1 (floored so m stays
        // finite).
        const double chi2 = std::max(g * g, 1e-6);
        const double eta = r.lossAt1kHz * std::pow(f / 1000.0, r.lossExponent);
        modes.push_back({f, 1.0 / eta, 1.0 / (meanInverseMass * chi2)});
    }
}

/// Radiation of the statistical and band modes (BodyRadiation.h): sigma from the efficiency curve; the sign
/// of a mode's net volume velocity is as random as its shape (drawn from a generator of its own, so the
/// modes themselves stay those of the seed). A band mode stands for many modes of random sign, so its sign
/// is random too: with one sign for all, their mass lines add coherently above their resonances and lift
/// the radiated level at 4-8 kHz 4-12 dB above what the full set of modes radiates (32 seeds).
void assignRadiation(BodyParameters& body, std::size_t firstStatistical, std::uint32_t seed)
{
    PortableRandom signs(seed ^ 0x5eed51u);
    for (std::size_t k = firstStatistical; k < body.modes.size(); ++k)
    {
        BodyMode& m = body.modes[k];
        m.radiationEfficiency = statisticalRadiationEfficiency(body.radiation, m.frequency);
        m.radiationSign = signs.uniform() < 0.5 ? -1.0 : 1.0;
    }
}

BodyParameters assemble(const char* name, const std::vector<BodyMode>& lowModes, const StatisticalRecipe& r,
                        const BodyRadiation& radiation, std::uint32_t seed, double maxFrequencyHz,
                        bool denseModes)
{
    if (!(maxFrequencyHz > 0.0) || !std::isfinite(maxFrequencyHz))
        throw std::invalid_argument("body: maxFrequencyHz must be positive and finite");
    BodyParameters body;
    body.name = name;
    body.radiation = radiation;
    for (const auto& m : lowModes)
        if (m.frequency < maxFrequencyHz)
            body.modes.push_back(m);
    const std::size_t firstStatistical = body.modes.size();
    const double denseLimit = denseModes ? maxFrequencyHz : std::min(r.denseLimitHz, maxFrequencyHz);
    appendStatisticalModes(body.modes, r, seed, denseLimit);
    if (denseLimit < maxFrequencyHz)
        appendBandModes(body.modes, r, denseLimit, maxFrequencyHz);
    assignRadiation(body, firstStatistical, seed);
    return body;
}

// Cello low modes [M ranges of [Notes §5.2]; chosen values A]. Wolf check ([Notes §5.2] / eq. 6.3, cello
// D string Z0 = 0.547 kg/s, v_b = 0.1 m/s, beta = 0.1, dmu = 0.8: F_min = Z0^2 v_b Re Y / (2 beta^2 dmu)
// = 1.87 N per s/kg of Re Y) [D]:
//  * B1+ at 194 Hz (between F#3 and G3), Q 40, m 0.2 kg: peak Re Y = Q / (m w) = 0.164 s/kg (0.166 with the
//    other modes) -> F_min ~ 0.31 N: inside the playing range, a mild wolf (0.41 N for m = 0.15 kg in §5.2).
//  * B1- at 176 Hz (F3) -> Re Y 0.066 s/kg, F_min ~ 0.12 N: a slight secondary tendency, as on many cellos.
//  * every other low mode stays below ~0.07 N; between modes (e.g. 120 Hz) Re Y ~ 1e-3 s/kg -> F_min ~ 1 mN.
// Scaled peak admittance Z0 Re Y ~ 0.09 here vs ~0.05 for the violin set below (Z0 ~ 0.3 kg/s on its G
// string): ~5 dB higher for the cello, as reported in [Notes §5.2] [V2: EUPH 9.4].
// Radiation (fourth and fifth numbers: sigma and the sign of the net volume velocity; BodyRadiation.h): the
// cello's signature modes are the violin's scaled ~2.1x in size, so each has the violin homologue's ka and
// its radiation efficiency [A]: B1- 0.12 and B1+ 0.11 ([Bissinger2008]), C1 and CBR, which move little net
// volume, at Bissinger's low end (0.004 and 0.01). A0 radiates through the f-holes, not through corpus
// motion; its sigma is set so that half its losses are radiation [A] (0.5 rho_s omega / (rho0 c0 Q)).
const std::vector<BodyMode> celloLowModes = {
    {62.0, 30.0, 2.0, 0.004, 1.0},  // C1: neck/body bending; weak at the bridge (large mass)
    {102.0, 30.0, 1.5, 0.062, 1.0}, // A0: Helmholtz-like air mode, weak at the bridge
    // C2 / CBR: kept weak (F_min ~ 0.07 N) so the open D3 (146.8 Hz) has no wolf
    {150.0, 30.0, 0.9, 0.01, -1.0},
    {176.0, 35.0, 0.5, 0.12, 1.0},  // B1- (T1): first corpus bending, lower
    {194.0, 40.0, 0.2, 0.11, 1.0},  // B1+ (C3): strongest at the bridge -> the wolf near F#3-G3
    {290.0, 30.0, 0.8, 0.145, 1.0}, // a further corpus mode ([Notes §5.2]: 250-700 Hz, m 0.3-2 kg)
};

// Cello statistical set [D with A inputs; [Notes §5.3] and body.py]:
//  * n_f: spruce top 0.033 /Hz + maple back 0.035 /Hz ~ 0.07 /Hz (mean spacing ~14 Hz);
//  * Re Y_skel 0.015 s/kg: between the plates' infinite-plate levels 0.012 and 0.017 s/kg, giving
//    <1/m> = 0.86 /kg (<m> ~ 1.2 kg); crossover 550 Hz, where the modal overlap eta f n_f ~ 0.8;
//  * bridge hill at 1.6 kHz (the violin's 2.6 kHz scaled down for the larger, heavier bridge), Q_h = 1.3:
//    Re Y_skel peaks at 1.7 x 0.015 s/kg; Q_h = 1/(w_h m_b Y_v) implies an effective bridge mass m_b ~ 5 g.
//    Above the hill Re Y_skel falls as f^-4 (bridge mass): ~0.1 x at 3.2 kHz, ~5e-3 x at 6.4 kHz;
//  * eta = 0.025 at 1 kHz rising as f^0.3 (0.021 at 550 Hz, 0.05 at 10 kHz).
constexpr StatisticalRecipe celloRecipe{550.0, 0.07, 0.015, 1600.0, 1.3, 0.025, 0.3, 1200.0};

// Cello radiation [A]: plates ~4.5 mm thick, spruce top (~450 kg/m^3) 2.0 kg/m^2 and maple back (~650 kg/m^3)
// 2.9 kg/m^2, mean rho_s 2.4 kg/m^2 (wood handbook densities); the violin's efficiency and directivity
// curves scaled down by the length ratio 2.1 (BodyRadiation.h); listener at 1 m.
constexpr BodyRadiation celloRadiation{2.4, 1.0, 2000.0, 1900.0};

// Violin low modes [A, from violin-family literature ranges]: A0 ~ 275 Hz, CBR ~ 405 Hz, B1- ~ 465 Hz,
// B1+ ~ 540 Hz, lighter than the cello's. B1+ peak Re Y = 40 / (0.07 * 2 pi 540) = 0.17 s/kg.
const std::vector<BodyMode> violinLowModes = {
    {185.0, 20.0, 0.8, 0.004, 1.0},  // C1: neck/body bending, weak at the bridge
    {275.0, 20.0, 0.5, 0.162, 1.0},  // A0: air mode (sigma: half its losses radiated, as the cello's)
    {405.0, 40.0, 0.35, 0.01, -1.0}, // CBR: centre-bout rhomboid, weak at the bridge
    {465.0, 40.0, 0.12, 0.12, 1.0},  // B1-
    {540.0, 40.0, 0.07, 0.11, 1.0},  // B1+: strongest at the bridge
    {640.0, 35.0, 0.25, 0.152, 1.0}, // a further corpus mode
};

// Violin statistical set [D with A inputs]: equivalent plates (top 2.8 mm spruce, back 3 mm maple, ~0.055 m^2
// each) give n_f ~ 0.012 + 0.012 = 0.023 /Hz (spacing ~43 Hz) and a top-plate Y_inf ~ 0.045 s/kg; skeleton
// 0.035 s/kg (<m> ~ 0.16 kg); crossover 750 Hz; bridge hill at 2.6 kHz with Q_h = 1.5 (peak Re Y_skel
// 0.08 s/kg, effective bridge mass ~1 g), inside the 2-3 kHz range of [Notes §5.3] item 5.
constexpr StatisticalRecipe violinRecipe{750.0, 0.023, 0.035, 2600.0, 1.5, 0.025, 0.3, 1500.0};

// Violin radiation [A]: top 2.8 mm spruce 1.2 kg/m^2, back 3 mm maple 1.9 kg/m^2, mean rho_s 1.55 kg/m^2;
// sigma reaches 1 at 4.2 kHz and directivity 2 at 4 kHz ([Bissinger2008], BodyRadiation.h); listener at 1 m.
constexpr BodyRadiation violinRadiation{1.55, 1.0, 4200.0, 4000.0};

} // namespace

std::complex<double> BodyParameters::admittance(double frequencyHz) const
{
    // [Notes] eq. 5.2: Y(w) = sum_k i w / ( m_k (w_k^2 - w^2 + i w w_k / Q_k) ).
    const double w = twoPi * frequencyHz;
    std::complex<double> y = 0.0;
    for (const auto& m : modes)
    {
        const double wk = twoPi * m.frequency;
        y += std::complex<double>(0.0, w) /
             (m.effectiveMass * std::complex<double>(wk * wk - w * w, w * wk / m.q));
    }
    return y;
}

BodyParameters rigidBody()
{
    return BodyParameters{};
}

BodyParameters celloBody(std::uint32_t seed, double maxFrequencyHz, bool denseModes)
{
    return assemble("cello", celloLowModes, celloRecipe, celloRadiation, seed, maxFrequencyHz, denseModes);
}

BodyParameters violinBody(std::uint32_t seed, double maxFrequencyHz, bool denseModes)
{
    return assemble("violin", violinLowModes, violinRecipe, violinRadiation, seed, maxFrequencyHz,
                    denseModes);
}

BodyParameters bodyByName(const std::string& name)
{
    if (name == "cello")
        return celloBody();
    if (name == "violin")
        return violinBody();
    if (name == "rigid")
        return rigidBody();
    throw std::invalid_argument("unknown body \"" + name +
                                "\": expected one of \"cello\", \"violin\", \"rigid\"");
}

} // namespace rosin::physics
