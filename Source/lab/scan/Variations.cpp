#include "lab/scan/Variations.h"

namespace rosin::scan
{

void applyVariations(ModelSpec& model, const ModelVariations& v)
{
    auto& calibration = model.contact.calibration;
    calibration.layerThickness = v.layerThickness.value_or(calibration.layerThickness);
    calibration.radius = v.contactRadius.value_or(calibration.radius);
    if (v.scaling)
    {
        // The calibration contact is only ever evaluated at its own reference force, where both scalings give
        // the same radius; it follows the bowing contact so that the summary names one law.
        model.contact.rig.scaling = *v.scaling;
        calibration.scaling = *v.scaling;
    }
    model.fingerDamping = model.fingerDamping || v.fingerDamping;
    if (v.rigidBridge)
        model.body = "rigid";
    if (v.noTorsion)
        model.torsion = false;
    if (v.noStiffness)
        model.bendingStiffness = false;
    if (v.horsehair)
        model.bow = physics::horsehairBow(model.bow.width);
    model.bow.width = v.bowWidth.value_or(model.bow.width);
}

const char* scalingName(physics::ContactScaling scaling) noexcept
{
    return scaling == physics::ContactScaling::Hertz ? "hertz" : "coulomb";
}

nlohmann::json variationsJson(const ModelSpec& m)
{
    return {{"torsion", m.torsion},
            {"bendingStiffness", m.bendingStiffness},
            {"rigidBridge", m.body == "rigid"},
            {"fingerDamping", m.fingerDamping},
            {"contactScaling", scalingName(m.contact.rig.scaling)},
            {"calibrationContactRadius", m.contact.calibration.radius},
            {"calibrationLayerThickness", m.contact.calibration.layerThickness},
            {"bowWidth", m.bow.width},
            {"compliantHair", m.bow.compliantHair}};
}

} // namespace rosin::scan
