#include "lab/discovery/StringFields.h"

namespace rosin::discovery
{

const std::vector<StringField>& stringFields()
{
    using P = physics::StringParameters;
    // The spec bounds only the required three (> 0); the optional ones get the bounds the model needs:
    // losses and stiffness may be zero (an ideal string), wave speed, Q and impedance may not.
    static const std::vector<StringField> fields{
        {"tension", &P::tension, {.min = 0.0, .unit = "N", .minOpen = true}, true},
        {"massPerLength", &P::massPerLength, {.min = 0.0, .unit = "kg/m", .minOpen = true}, true},
        {"length", &P::length, {.min = 0.0, .unit = "m", .minOpen = true}, true},
        {"bendingStiffness", &P::bendingStiffness, {.min = 0.0, .unit = "N m^2"}, false},
        {"lossF", &P::lossF, {.min = 0.0}, false},
        {"lossB", &P::lossB, {.min = 0.0}, false},
        {"lossA", &P::lossA, {.min = 0.0}, false},
        {"torsionalWaveSpeed", &P::torsionalWaveSpeed, {.min = 0.0, .unit = "m/s", .minOpen = true}, false},
        {"torsionalQ", &P::torsionalQ, {.min = 0.0, .minOpen = true}, false},
        {"torsionalImpedance", &P::torsionalImpedance, {.min = 0.0, .unit = "kg/s", .minOpen = true}, false},
    };
    return fields;
}

} // namespace rosin::discovery
