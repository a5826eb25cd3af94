#pragma once
// The rig.string fields of the spec, their bounds and where they go in physics::StringParameters. One table
// for the reader, the writer and the note on defaults.
#include <vector>

#include "core/physics/string/StringParameters.h"
#include "lab/discovery/FieldChecks.h"

namespace rosin::discovery
{

struct StringField
{
    const char* name;
    double physics::StringParameters::*member;
    Range range;
    bool required; ///< tension, massPerLength, length; the others default to cello-D3's values
};

/// In the spec's order: tension, massPerLength, length, bendingStiffness, lossF, lossB, lossA,
/// torsionalWaveSpeed, torsionalQ, torsionalImpedance.
const std::vector<StringField>& stringFields();

/// The catalogue string whose values fill the optional fields a dataset leaves out.
inline constexpr const char* kDefaultString = "cello-D3";

} // namespace rosin::discovery
