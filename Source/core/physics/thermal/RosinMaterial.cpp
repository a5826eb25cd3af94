// Which rosin the contact is made of (RosinMaterial.h).
#include "core/physics/thermal/RosinMaterial.h"

#include <stdexcept>

namespace rosin::physics
{

namespace
{
bool isHandbookRosin(const ThermalMaterial& m)
{
    return m.conductivity == materials::rosin.conductivity &&
           m.volumetricHeatCapacity == materials::rosin.volumetricHeatCapacity;
}
} // namespace

ThermalMaterial rosinWithHeatCapacityFactor(double factor)
{
    ThermalMaterial r = materials::rosin;
    r.volumetricHeatCapacity *= factor;
    return r;
}

ThermalMaterial rosinMaterial(RosinMaterial which)
{
    return which == RosinMaterial::Calibrated
               ? rosinWithHeatCapacityFactor(kCalibratedRosinHeatCapacityFactor)
               : materials::rosin;
}

ContactMaterials withRosin(ContactMaterials m, const ThermalMaterial& rosin)
{
    for (ThermalMaterial* side : {&m.layer, &m.stationary, &m.moving})
        if (isHandbookRosin(*side))
            *side = rosin;
    return m;
}

const std::vector<std::string>& rosinMaterialNames()
{
    static const std::vector<std::string> names = {"handbook", "calibrated"};
    return names;
}

RosinMaterial rosinMaterialFromName(const std::string& name)
{
    if (name == "handbook")
        return RosinMaterial::Handbook;
    if (name == "calibrated")
        return RosinMaterial::Calibrated;
    throw std::invalid_argument("unknown rosin material \"" + name + "\" (handbook or calibrated)");
}

} // namespace rosin::physics
