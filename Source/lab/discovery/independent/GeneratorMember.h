#pragma once
// The independent generator as a family: each member is the same physics simulated with other numerics,
// other constants within their handbook priors and another measurement chain, so that rosin discover is
// judged on simulators it was not developed against rather than on one. A member is drawn from its number
// (member 0 is the generator's nominal design, what `--generator independent` has always produced);
// `rosin synth-data --generator independent --member K` makes a dataset with member K. What a member draws,
// uniform within the ranges below:
//   * numerics: the internal rate (2, 3 or 4 x the dataset's), the loss filter's upper fit (harmonic 24-48),
//     the dispersion cascade's fit band (up to 7-12 kHz), the heat balance's grid (surface cell 0.3-0.8 of a
//     step's diffusion length, spacing ratio 1.15-1.4) and its advection width (0.8-1.25 contact radii);
//   * constants discover does not calibrate: the torsional wave speed (x0.95-1.05), Q (x0.8-1.25) and
//     impedance (x0.9-1.1) ([Galluzzo2017] Table 1 gives them to no better);
//   * the chain: the anti-aliasing low-pass's order (2, 4 or 6; its corner stays the seed's draw);
//   * the rig: with its preset's body (three in four members) or on a rigid bridge. This one the dataset
//     states (dataset.json's rig.body), as a laboratory would: it is a different rig, not a hidden one.
// Members 1-99 are the tuning split, to develop against; members from 100 up are the sealed split, which
// the tests only score (with seeds from 1000 up) and nothing is tuned on.
// JUCE-free.
#include <string>
#include <utility>
#include <vector>

#include "core/config/Preset.h"
#include "core/physics/string/StringParameters.h"

namespace rosin::discovery
{

struct GeneratorMember
{
    unsigned number = 0;
    int oversampling = 2;               ///< internal rate / dataset rate
    double lossFitHarmonic = 36.0;      ///< the loss filter's second fit frequency, x f0
    double dispersionFitTopHz = 10000.; ///< the dispersion cascade is fitted to partials below this
    double heatSurfaceCell = 0.5;       ///< the heat grid's first cell, x sqrt(diffusivity dt)
    double heatGridGrowth = 1.25;       ///< the heat grid's spacing ratio
    double advectionWidth = 1.0;        ///< the width of rosin carried through the contact, x its radius
    double torsionalWaveSpeed = 1.0;    ///< x the string's stated value
    double torsionalQ = 1.0;            ///< x the string's stated value
    double torsionalImpedance = 1.0;    ///< x the string's stated value
    int antiAliasOrder = 4;             ///< the chain's Butterworth low-pass order (2, 4 or 6)
    bool body = true;                   ///< false: the rig stands on a rigid bridge (stated in dataset.json)

    std::vector<std::pair<std::string, double>> values() const;
    /// `string` with this member's torsional constants.
    physics::StringParameters torsionOf(physics::StringParameters string) const;
};

/// Member `number` of the family (0: the nominal design).
GeneratorMember generatorMember(unsigned number);

/// The rig a member's dataset states: its preset's, on a rigid bridge where the member has no body.
void applyMemberRig(const GeneratorMember& member, config::Preset& preset);

inline constexpr unsigned kFirstSealedMember = 100;
/// True for the sealed split's members: tests score them, nothing is tuned on them.
inline bool isSealedMember(unsigned number) noexcept
{
    return number >= kFirstSealedMember;
}

} // namespace rosin::discovery
