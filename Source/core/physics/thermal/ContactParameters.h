#pragma once
// Geometry and materials of the rosin contact ([Galluzzo2017] Table 2; [Notes §2.3-2.7]).
#include <string>

#include "core/physics/thermal/ThermalMaterial.h"

namespace rosin::physics
{

/// How the real contact area grows with the normal force.
enum class ContactScaling
{
    Coulomb, ///< A proportional to N (radius proportional to sqrt N): [Galluzzo2017]'s choice
    Hertz    ///< A proportional to N^(2/3) (radius proportional to N^(1/3)): single elastic contact
};

/// A contact disc of radius `radius` at `referenceForce`, with a softened rosin layer `layerThickness`.
struct ContactGeometry
{
    double radius = 250e-6;       ///< a_ref, m
    double referenceForce = 1.0;  ///< N_ref, N
    double layerThickness = 1e-6; ///< delta, m
    ContactScaling scaling = ContactScaling::Coulomb;
    /// Contact radius at normal force N (m).
    double radiusAt(double normalForce) const;
};

/// Everything the thermal friction laws need besides the sample rate.
struct ContactParameters
{
    ContactGeometry rig; ///< the bowing contact: Galluzzo rig by default
    ContactGeometry calibration{500e-6, 3.0, 10e-6, ContactScaling::Coulomb}; ///< steady-sliding rig
    ContactMaterials
        materials; ///< rosin layer, stationary and moving solids ([Galluzzo2017]: acrylic rod on a string)
    double ambientOffset = 0.0; ///< K: rosin temperature at rest minus the calibration's ambient
};

/// [Galluzzo2017] Table 2 contact for the Galluzzo rig (250 um at 1 N, 1 um layer).
ContactParameters galluzzoContact();
/// [Galluzzo2017] Table 2 contact for the Schumacher rig (200 um at 1 N, 1 um layer).
ContactParameters schumacherContact();

} // namespace rosin::physics
