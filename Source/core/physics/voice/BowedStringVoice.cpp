#include "core/physics/voice/BowedStringVoice.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>

#include "core/physics/body/BridgeBody.h"
#include "core/physics/bow/BowRibbon.h"
#include "core/physics/bow/SlipNoise.h"
#include "core/physics/modal/ModalKernels.h"
#include "core/physics/modal/VectorBlock.h"
#include "core/physics/units/Range.h"

namespace rosin::physics
{

namespace
{
constexpr double pi = std::numbers::pi;
// Parameter changes of beta and finger position are applied at most this often (samples): recomputing the
// modal weights costs one sin() per mode, recomputing poles one exp() per mode.
constexpr int kControlInterval = 16;
} // namespace

/// Everything per-sample lives here; see BowedStringVoice.h for the formulation.
struct BowedStringVoice::Impl
{
    // String as currently vibrating.
    StringParameters string;
    double openLength = 0.69, length = 0.69, beta = 0.1, fingerRatio = 1.0;
    bool stopped = false, torsionOn = true;
    double lossScale = 1.0; // VoiceConfig::lossScale
    BowParameters bow;      // VoiceConfig::bow
    HairTerms hair;
    HairState hairState;
    double hairH = 0.0; // this sample's hair history, between solveJunction() and finishStep()
    SlipNoise slipNoise;
    double T = 1.0 / 48000.0, modeLimit = 0.0; // rad/s

    ModalBank trans, tors;
    BridgeBody ownBody;
    BridgeBody* body = &ownBody; // ownBody, or a body shared by several strings (BowedInstrument)
    std::vector<ModeSpec> transSpecs, torsSpecs;
    std::vector<double> transActive, torsActive; // 1 for modes below the frequency limit, else 0
    std::vector<double> aN, bN;                  // string inputs x_n = aN f + bN (-u'')
    std::vector<double> transPhi;                // bow coupling of each transverse mode (corrected shape)
    std::vector<double> torsGain;
    std::vector<ModalReal> aIn, bIn, torsIn; // aN, bN, torsGain in the modal kernels' number type
    OutputWeights transVel, transAcc, torsVel;

    // Direct (instantaneous) coefficients of the coupled bow/bridge solve (JunctionTerms.h), the full-band
    // correction of the bow admittance c (1 - z^-1) included: see updateWeights().
    JunctionTerms j;
    // This sample's junction, between solveJunction() and finishStep().
    JunctionSolution solution;
    double bowVelocity = 0;
    double previousFriction = 0.0;
    // Histories: outputs of the state before the current input.
    double Sv = 0, Sa = 0, Tv = 0;
    // Last step's inputs (energy and displacement inspection).
    double lastF = 0, lastBridge = 0, lastUdd = 0;
    long sampleCounter = 0;

    void buildModes(const VoiceConfig& cfg, double fs);
    void computeTransSpecs();
    void computeTorsSpecs();
    void updateWeights();
    void applyControl(const BowInput& in);
    void setPosition(double newBeta, double finger);
    void clearState();
    double energy() const;
    /// The junction's histories now: the string's and the body's.
    JunctionHistories histories() const noexcept
    {
        return {Sv,
                Sa,
                Tv,
                body->displacementHistory(),
                body->velocityHistory(),
                body->accelerationHistory(),
                previousFriction};
    }
};

void BowedStringVoice::Impl::computeTransSpecs()
{
    for (std::size_t i = 0; i < transSpecs.size(); ++i)
    {
        const int n = static_cast<int>(i) + 1;
        double omega = string.modeAngularFrequency(n, length);
        transActive[i] = omega < modeLimit ? 1.0 : 0.0;
        omega = std::min(omega, modeLimit); // inactive modes are parked below the limit with zero weight
        transSpecs[i] = {omega, lossScale * string.lossFactor(n, length, stopped)};
    }
}

void BowedStringVoice::Impl::computeTorsSpecs()
{
    for (std::size_t i = 0; i < torsSpecs.size(); ++i)
    {
        const int n = static_cast<int>(i) + 1;
        double omega = n * pi * string.torsionalWaveSpeed / length;
        torsActive[i] = omega < modeLimit ? 1.0 : 0.0;
        torsSpecs[i] = {std::min(omega, modeLimit), 1.0 / string.torsionalQ};
    }
}

void BowedStringVoice::Impl::buildModes(const VoiceConfig& cfg, double fs)
{
    T = 1.0 / fs;
    modeLimit = 2.0 * pi * cfg.maxModeFrequencyRatio * fs;
    int nTrans = 0;
    while (nTrans < cfg.maxTransverseModes && string.modeAngularFrequency(nTrans + 1, openLength) < modeLimit)
        ++nTrans;
    int nTors = 0;
    if (cfg.torsion)
        while (nTors < cfg.maxTorsionalModes &&
               (nTors + 1) * pi * string.torsionalWaveSpeed / openLength < modeLimit)
            ++nTors;
    // Pad each bank to whole kernel blocks with silent modes (zero input and output weights): the kernels
    // then run without scalar tails.
    nTrans = paddedToWholeBlocks(nTrans, kModalBlock);
    nTors = cfg.torsion ? paddedToWholeBlocks(nTors, kModalBlock) : 0;
    transSpecs.assign(nTrans, {});
    transActive.assign(nTrans, 1.0);
    torsSpecs.assign(nTors, {});
    torsActive.assign(nTors, 1.0);
    computeTransSpecs();
    computeTorsSpecs();
    trans.configure(transSpecs, fs);
    tors.configure(torsSpecs, fs);

    ownBody.configure(cfg.body, fs, modeLimit, false); // the lab's voice: its sound is heard elsewhere
    aN.assign(nTrans, 0.0);
    transPhi.assign(nTrans, 0.0);
    bN.assign(nTrans, 0.0);
    torsGain.assign(nTors, 0.0);
    aIn.assign(nTrans, ModalReal(0));
    bIn.assign(nTrans, ModalReal(0));
    torsIn.assign(nTors, ModalReal(0));
    transVel.assign(nTrans);
    transAcc.assign(nTrans);
    torsVel.assign(nTors);
}

namespace
{
// Under a velocity constraint (a sticking bow) a sampled mode yields as if its compliance were
// (x / sin x)^2 / omega^2, x = omega T / 2, not 1/omega^2: twice too soft at the 0.45 fs mode limit. Scaling
// the bow's coupling to mode n by sin(x)/x on both the force input and the velocity output restores each
// mode's static compliance at the bow (the quasi-static pre-slip rise of [Woodhouse-thermal] eqs. 3-5), keeps
// the bow port reciprocal, and tames the top modes' share of the bow admittance.
double staticCorrection(const ModalBank& bank, int i, double T)
{
    const double x = 0.5 * bank.s[i].imag() * T;
    return std::sin(x) / x;
}
} // namespace

// Mode weights for the current beta and length, and the direct coefficients of the per-sample solve.
void BowedStringVoice::Impl::updateWeights()
{
    const double m = string.massPerLength, P = string.tension, L = length;
    const double mL = m * L;
    double B1 = 0, Ya = 0, A1 = 0, Bv = 0;
    // The ribbon's mean over its width (BowRibbon.h); a point bow's factors are exactly 1.
    const double W = ribbonWidthOnString(bow.width, beta, L);
    for (int i = 0; i < trans.size(); ++i)
    {
        const int n = i + 1;
        const double phi = std::sin(n * pi * beta) * ribbonModeFactor(n, W, L) * transActive[i] *
                           staticCorrection(trans, i, T);
        const double c = mL / (n * pi) * transActive[i]; // bridge-force weight of q''_n (Lagrangian coupling)
        aN[i] = 2.0 * phi / mL;                          // bow force -> mode n
        bN[i] = 2.0 / (n * pi) * transActive[i];         // bridge acceleration -> mode n (times -u'')
        transPhi[i] = phi;
        aIn[i] = static_cast<ModalReal>(aN[i]);
        bIn[i] = static_cast<ModalReal>(bN[i]);
        const auto rv = 2.0 * phi * trans.residue(i, ModalOutput::Velocity);
        const auto ra = 2.0 * c * trans.residue(i, ModalOutput::Acceleration);
        transVel.set(i, rv);
        transAcc.set(i, ra);
        const double V = trans.direct(i, ModalOutput::Velocity);
        const double E = trans.direct(i, ModalOutput::Acceleration);
        A1 += c * E * aN[i];
        B1 += c * E * bN[i];
        Ya += phi * V * aN[i];
        Bv += phi * V * bN[i];
    }
    // Torsion: a second "string" of tension Zt ct and mass Zt/ct per length, referred to the surface.
    const double mt = string.torsionalImpedance / string.torsionalWaveSpeed;
    for (int i = 0; i < tors.size(); ++i)
    {
        const double phi = std::sin((i + 1) * pi * beta) * ribbonModeFactor(i + 1, W, L) * torsActive[i] *
                           staticCorrection(tors, i, T);
        torsGain[i] = 2.0 * phi / (mt * L);
        torsIn[i] = static_cast<ModalReal>(torsGain[i]);
        const auto rv = 2.0 * phi * tors.residue(i, ModalOutput::Velocity);
        torsVel.set(i, rv);
        Ya += phi * tors.direct(i, ModalOutput::Velocity) * torsGain[i];
    }
    const double U0 = body->displacementDirect();
    const double U1 = body->velocityDirect();
    const double U2 = body->accelerationDirect();
    // Bridge force F = (1-beta) f - (P/L) u - (mL/3) u'' - sum_n c_n q''_n, with every term = history +
    // direct.
    const double M3 = mL / 3.0 - B1;
    const double bridgeCoupling = (P / L) * U0 + M3 * U2; // c: F = R - c G, G the total bridge force
    const double D = 1.0 + bridgeCoupling;
    const double kappa = (1.0 - beta - A1) / D;
    double y0 = Ya - Bv * U2 * kappa + (1.0 - beta) * U1 * kappa;
    // A string answers a sudden force at a point with v = f / (2 Z_eff) at once ([MSW1983],
    // Woodhouse; [Notes] eq. 1.2). The modal bank stops at 0.45 fs, so it spreads that delta over two
    // samples and its admittance almost vanishes at Nyquist: a sticking contact (a velocity constraint) then
    // lets the friction force ring at Nyquist. Adding c (1 - z^-1), c = 1/(2 Z_eff) - y0, moves the spread
    // back into the current sample: the instantaneous admittance becomes the physical one, the admittance at
    // low frequency is unchanged, and Re c (1 - e^-iwT) >= 0 keeps the bow port passive.
    // Over a ribbon the physical answer is the share of it that the ribbon's mean velocity keeps within the
    // sample (BowRibbon.h), per wave type: 1/(2 Z_eff) = 1/(2 Z0) + 1/(2 Zt).
    const double Z0 = string.impedance();
    const double Zeff = torsionOn ? Z0 * string.torsionalImpedance / (Z0 + string.torsionalImpedance) : Z0;
    double physicalY0 = 1.0 / (2.0 * Zeff);
    if (W > 0.0)
    {
        physicalY0 = ribbonDirectShare(string.waveSpeed(), T, W) / (2.0 * Z0);
        if (torsionOn)
            physicalY0 +=
                ribbonDirectShare(string.torsionalWaveSpeed, T, W) / (2.0 * string.torsionalImpedance);
    }
    const double bandCorrection = std::max(0.0, physicalY0 - y0);
    y0 += bandCorrection;
    j = {beta, P / L, M3, D, A1, Bv, U0, U1, U2, y0, bandCorrection, bridgeCoupling};
}

void BowedStringVoice::Impl::clearState()
{
    trans.reset();
    tors.reset();
    ownBody.reset();
    Sv = Sa = Tv = 0;
    lastF = lastBridge = lastUdd = previousFriction = 0;
    hairState = {};
    hairH = 0.0;
    solution = {};
    slipNoise.reset();
}

BowedStringVoice::BowedStringVoice() : impl_(std::make_unique<Impl>()) {}
BowedStringVoice::~BowedStringVoice() = default;

void BowedStringVoice::prepare(const VoiceConfig& config, std::unique_ptr<FrictionLaw> friction,
                               double sampleRate)
{
    if (!friction)
        throw std::invalid_argument("BowedStringVoice::prepare: a friction law is required");
    if (!(sampleRate >= limits::sampleRate.min && sampleRate <= limits::sampleRate.max))
        throw std::invalid_argument("BowedStringVoice::prepare: sample rate must be " +
                                    formatNumber(limits::sampleRate.min) + ".." +
                                    formatNumber(limits::sampleRate.max) + " Hz");
    config_ = config;
    sampleRate_ = sampleRate;
    auto& s = *impl_;
    s.string = config.string;
    if (!config.bendingStiffness)
        s.string.bendingStiffness = 0.0;
    s.openLength = s.length = config.string.length;
    s.beta = 0.1;
    s.fingerRatio = 1.0;
    s.stopped = false;
    s.torsionOn = config.torsion;
    if (!(config.lossScale > 0.0))
        throw std::invalid_argument("BowedStringVoice::prepare: lossScale must be > 0");
    s.lossScale = config.lossScale;
    validateBow(config.bow, "BowedStringVoice::prepare");
    s.bow = config.bow;
    s.hair = hairTerms(config.bow, sampleRate);
    // Each string its own stream, the same on every run (libstdc++'s string hash is fixed).
    s.slipNoise.prepare(config.bow.slipNoise, sampleRate, std::hash<std::string>{}(config.string.name));
    s.buildModes(config, sampleRate);
    s.updateWeights();
    friction_ = std::move(friction);
    friction_->prepare(sampleRate);
    reset();
}

void BowedStringVoice::reset() noexcept
{
    impl_->clearState();
    impl_->sampleCounter = 0;
    if (friction_)
        friction_->reset();
    recovered_ = false;
}

VoiceSample BowedStringVoice::step(const BowInput& in) noexcept
{
    const double R = solveJunction(in, 0.0);
    // Alone on its body, the string's force is the whole bridge force: G = R - c G.
    const double G = R / (1.0 + impl_->j.bridgeCoupling);
    const VoiceSample out = finishStep(G);
    if (impl_->body == &impl_->ownBody)
        impl_->ownBody.advance(recovered_ ? 0.0 : G);
    return out;
}

void BowedStringVoice::Impl::applyControl(const BowInput& in)
{
    const bool controlTick = (sampleCounter++ % kControlInterval) == 0;
    if (controlTick)
        setPosition(std::clamp(in.beta, 0.01, 0.5), std::clamp(in.fingerRatio, 0.1, 1.0));
}

void BowedStringVoice::Impl::setPosition(double newBeta, double finger)
{
    if (finger != fingerRatio)
    {
        fingerRatio = finger;
        length = openLength * finger;
        stopped = finger < 0.999;
        computeTransSpecs();
        computeTorsSpecs();
        trans.retune(transSpecs.data(), trans.size());
        tors.retune(torsSpecs.data(), tors.size());
        beta = newBeta;
        updateWeights();
    }
    else if (newBeta != beta)
    {
        beta = newBeta;
        updateWeights();
    }
}

void BowedStringVoice::setBowPosition(double beta, double fingerRatio)
{
    impl_->setPosition(std::clamp(beta, 0.01, 0.5), std::clamp(fingerRatio, 0.1, 1.0));
}

VoiceCoefficients BowedStringVoice::coefficients() const noexcept
{
    const auto& s = *impl_;
    VoiceCoefficients c;
    c.transverse = &s.trans;
    c.torsional = &s.tors;
    c.transverseForceGain = s.aIn.data();
    c.transverseBridgeGain = s.bIn.data();
    c.torsionalForceGain = s.torsIn.data();
    c.transverseVelocity = &s.transVel;
    c.transverseAcceleration = &s.transAcc;
    c.torsionalVelocity = &s.torsVel;
    c.body = s.body;
    c.junction = s.j;
    c.hair = s.hair;
    return c;
}

double BowedStringVoice::solveJunction(const BowInput& in, double otherStringsForce) noexcept
{
    auto& s = *impl_;
    recovered_ = false;
    s.applyControl(in);
    // What the bridge does this sample apart from this string's own force: the body's history plus its
    // instantaneous answer to the other strings' forces (predicted by the caller).
    const JunctionHistories h = s.histories();
    const double vh = s.j.loadLineHistory(h, otherStringsForce);
    s.bowVelocity = in.bowVelocity;
    // Compliant hair: the law sees the sliding speed against the hair's contact, not the stick (BowHair.h).
    double dvHistory = vh - in.bowVelocity;
    if (s.hair.admittance > 0.0)
    {
        s.hairH = hairHistory(s.hair, s.hairState);
        dvHistory -= s.hairH;
    }
    // The slip noise follows last sample's contact: while the string flies back under the ribbon its force
    // fluctuates; a held contact, and the small slips of a rounded corner, keep the law's own.
    const bool flyingBack = !s.solution.sticking && std::abs(s.solution.dv) > std::abs(in.bowVelocity);
    const double bowForce = std::max(0.0, in.bowForce) * s.slipNoise.forceFactor(flyingBack);
    s.solution = friction_->solve({dvHistory, 1.0 / (s.j.y0 + s.hair.admittance), bowForce});
    // Bridge force F = R - c G, G the total force on the bridge ([Notes §5.1], one string per port).
    return s.j.bridgeForceBeforeCoupling(s.solution.frictionForce, h);
}

double BowedStringVoice::bridgeCoupling() const noexcept
{
    return impl_->j.bridgeCoupling;
}

VoiceSample BowedStringVoice::finishStep(double totalBridgeForce) noexcept
{
    auto& s = *impl_;
    const double G = totalBridgeForce;
    const double f = s.solution.frictionForce;
    const JunctionHistories h = s.histories();
    const double F = s.j.bridgeForceBeforeCoupling(f, h) - s.j.bridgeCoupling * G;
    const double udd = h.udd + s.j.U2 * G;

    const TwoSums st =
        advanceTwoInputsTwoOutputs(s.trans, s.aIn.data(), f, s.bIn.data(), -udd, s.transVel, s.transAcc);
    s.Sv = st.first;
    s.Sa = st.second;
    s.Tv = s.tors.size() ? advanceOneInputOneOutput(s.tors, s.torsIn.data(), f, s.torsVel) : 0.0;
    s.lastF = f, s.lastBridge = F, s.lastUdd = udd;
    s.previousFriction = f;

    const double vb = s.bowVelocity;
    double stringVelocity = vb + s.solution.dv;
    if (s.hair.admittance > 0.0)
        stringVelocity += advanceHair(s.hair, s.hairState, s.hairH, f);
    VoiceSample out{F, stringVelocity, f, vb, friction_->contactTemperature(), s.solution.sticking};
    // A runaway (non-finite or absurd) state is reset rather than heard: nothing physical reaches 1e4 N here.
    if (!std::isfinite(F) || !std::isfinite(s.Sv) || std::abs(F) > 1e4)
    {
        reset();
        recovered_ = true;
        out = VoiceSample{};
        out.bowVelocity = vb;
    }
    return out;
}

namespace
{
int countNonZero(const std::vector<double>& v)
{
    return static_cast<int>(std::count_if(v.begin(), v.end(), [](double x) { return x != 0.0; }));
}
} // namespace

int BowedStringVoice::transverseModeCount() const noexcept
{
    return countNonZero(impl_->transActive);
}
int BowedStringVoice::torsionalModeCount() const noexcept
{
    return countNonZero(impl_->torsActive);
}
int BowedStringVoice::bodyModeCount() const noexcept
{
    return impl_->body->modeCount();
}
double BowedStringVoice::instantaneousAdmittance() const noexcept
{
    return impl_->j.y0;
}

std::vector<double> BowedStringVoice::transverseModeFrequencies() const
{
    std::vector<double> f;
    for (std::size_t i = 0; i < impl_->transSpecs.size(); ++i)
        if (impl_->transActive[i] != 0.0)
            f.push_back(impl_->transSpecs[i].angularFrequency / (2.0 * pi));
    return f;
}

double BowedStringVoice::Impl::energy() const
{
    const double m = string.massPerLength, L = length, mL = m * L;
    // The body's own energy is counted here only when this string owns it.
    double e = body == &ownBody ? ownBody.energyAtLastStep() : 0.0;
    const double u = body->displacementAtLastStep(), ud = body->velocityAtLastStep();
    double cross = 0;
    for (int i = 0; i < trans.size(); ++i)
    {
        const double in = aN[i] * lastF - bN[i] * lastUdd;
        const double q = trans.outputAtLastStep(i, ModalOutput::Displacement, in);
        const double qd = trans.outputAtLastStep(i, ModalOutput::Velocity, in);
        e += 0.25 * mL * (qd * qd + trans.modalStiffness(i) * q * q);
        cross += qd * bN[i];
    }
    // Kinetic cross term m u' sum q'_n L/(n pi), the quasi-static shape's own energy, and its tension energy.
    e += 0.5 * mL * ud * cross + mL / 6.0 * ud * ud + string.tension * u * u / (2.0 * L);
    e += 0.5 * hair.stiffness * hairState.x * hairState.x; // the stretched hair (0 for rigid hair)
    const double mt = string.torsionalImpedance / string.torsionalWaveSpeed;
    for (int i = 0; i < tors.size(); ++i)
    {
        const double in = torsGain[i] * lastF;
        const double q = tors.outputAtLastStep(i, ModalOutput::Displacement, in);
        const double qd = tors.outputAtLastStep(i, ModalOutput::Velocity, in);
        e += 0.25 * mt * L * (qd * qd + tors.modalStiffness(i) * q * q);
    }
    return e;
}

void BowedStringVoice::useSharedBody(BridgeBody* body)
{
    impl_->body = body ? body : &impl_->ownBody;
    impl_->updateWeights();
}

double BowedStringVoice::lastBridgeForce() const noexcept
{
    return impl_->lastBridge;
}

double BowedStringVoice::storedEnergy() const noexcept
{
    return impl_->energy();
}

double BowedStringVoice::bowPointDisplacement() const noexcept
{
    const auto& s = *impl_;
    double y = 0;
    const double u = s.body->displacementAtLastStep();
    for (int i = 0; i < s.trans.size(); ++i)
    {
        y += s.transPhi[i] *
             s.trans.outputAtLastStep(i, ModalOutput::Displacement, s.aN[i] * s.lastF - s.bN[i] * s.lastUdd);
    }
    return y + (1.0 - s.beta) * u;
}

} // namespace rosin::physics
