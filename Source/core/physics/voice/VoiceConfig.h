#pragma once
// Slow "instrument" parameters of one bowed-string voice: which string, which body, which model
// variations. Changing them means calling BowedStringVoice::prepare() again (off the audio thread).
#include "core/physics/body/BodyParameters.h"
#include "core/physics/bow/BowParameters.h"
#include "core/physics/string/StringParameters.h"

namespace rosin::physics
{

struct VoiceConfig
{
    StringParameters string;      ///< default: open cello D3 of the Galluzzo rig ([Galluzzo2017] Table 1)
    BodyParameters body;          ///< bridge admittance; empty (the default) is a rigid bridge
    bool torsion = true;          ///< include torsional modes ([Galluzzo2017] Fig. 12e turns them off)
    bool bendingStiffness = true; ///< include EI ([Galluzzo2017] Fig. 12f turns it off)
    double maxModeFrequencyRatio = 0.45; ///< keep modes below this fraction of the sample rate
    int maxTransverseModes = 400;        ///< hard cap on transverse modes
    int maxTorsionalModes = 80;          ///< hard cap on torsional modes
    /// Multiplies every transverse mode's loss factor: string losses above the nominal loss law (the
    /// discrepancy workflow's "extra-string-damping"; 1 = the loss law of [Galluzzo2017] Table 1).
    double lossScale = 1.0;
    /// The ribbon's width and the hair's give (BowParameters.h); the default is the seeds' point contact.
    BowParameters bow;
};

} // namespace rosin::physics
