#pragma once
// Model variations of [Galluzzo2017] section 3.3 as scan options, applied on top of a preset's model:
//   Fig. 9  layer thickness and Fig. 10 contact radius of the STEADY-SLIDING (calibration) contact on which
//           the thermal laws' material functions are fitted ([Galluzzo2017] Table 2, last column: 10 um, 500
//           um at 3 N; [Galluzzo2017] varies 10 -> 15 um and 0.5 -> 0.7 mm). The bowing contact keeps the
//           preset's values (a preset's "contact" object changes those).
//   Fig. 11 Coulomb or Hertz contact-area scaling of the bowing contact.
//   Fig. 12 c-f: finger-stopped damping, rigid bridge, no torsion, no bending stiffness.
//   And the bow the seeds' rods did not have: a ribbon's width and compliant horsehair (BowParameters.h).
#include <optional>

#include <nlohmann/json.hpp>

#include "lab/scan/ModelSpec.h"

namespace rosin::scan
{

struct ModelVariations
{
    std::optional<double> layerThickness; ///< m, calibration contact's softened layer delta
    std::optional<double> contactRadius;  ///< m, calibration contact's radius at its reference force
    std::optional<physics::ContactScaling> scaling;
    bool fingerDamping = false;
    bool rigidBridge = false;
    bool noTorsion = false;
    bool noStiffness = false;
    std::optional<double> bowWidth; ///< m, the ribbon's width on the string
    bool horsehair = false;         ///< compliant hair with the handbook horsehair's values
};

void applyVariations(ModelSpec& model, const ModelVariations& variations);

/// The model switches as the summary reports them: torsion, bendingStiffness, rigidBridge, fingerDamping,
/// contactScaling, calibrationContactRadius, calibrationLayerThickness, bowWidth, compliantHair.
nlohmann::json variationsJson(const ModelSpec& model);

/// "coulomb" / "hertz".
const char* scalingName(physics::ContactScaling scaling) noexcept;

} // namespace rosin::scan
