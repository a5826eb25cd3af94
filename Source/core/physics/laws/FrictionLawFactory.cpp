// Friction laws by name (FrictionLawFactory.h).
#include "core/physics/laws/FrictionLawFactory.h"

#include <array>
#include <stdexcept>

#include "core/physics/friction/CurveFrictionLaw.h"
#include "core/physics/thermal/ModifiedThermalLaw.h"
#include "core/physics/thermal/PlasticThermalLaw.h"
#include "core/physics/thermal/ViscousThermalLaw.h"

namespace rosin::physics
{

namespace
{
struct Entry
{
    FrictionModel model;
    const char* name;
};
constexpr std::array<Entry, 6> kModels{{{FrictionModel::Classical, "classical"},
                                        {FrictionModel::Reconstructed, "reconstructed"},
                                        {FrictionModel::Plastic, "plastic"},
                                        {FrictionModel::Viscous, "viscous"},
                                        {FrictionModel::ModifiedBow, "modified-bow"},
                                        {FrictionModel::ModifiedRod, "modified-rod"}}};
} // namespace

const char* frictionModelName(FrictionModel model)
{
    for (const auto& e : kModels)
        if (e.model == model)
            return e.name;
    throw std::invalid_argument("unknown FrictionModel value");
}

std::vector<std::string> frictionModelNames()
{
    std::vector<std::string> names;
    for (const auto& e : kModels)
        names.emplace_back(e.name);
    return names;
}

FrictionModel frictionModelFromName(const std::string& name)
{
    for (const auto& e : kModels)
        if (name == e.name)
            return e.model;
    std::string valid;
    for (const auto& e : kModels)
        valid += (valid.empty() ? "" : ", ") + std::string(e.name);
    throw std::invalid_argument("unknown friction model '" + name + "'; valid names: " + valid);
}

std::unique_ptr<FrictionLaw> makeFrictionLaw(FrictionModel model, const ContactParameters& contact)
{
    switch (model)
    {
    case FrictionModel::Classical:
        return std::make_unique<ClassicalFrictionLaw>(ClassicalCurve{}, "classical");
    case FrictionModel::Reconstructed:
        return std::make_unique<ReconstructedFrictionLaw>(ReconstructedCurve{}, "reconstructed");
    case FrictionModel::Plastic:
        return std::make_unique<PlasticThermalLaw>(contact);
    case FrictionModel::Viscous:
        return std::make_unique<ViscousThermalLaw>(contact);
    case FrictionModel::ModifiedBow:
        return std::make_unique<ModifiedThermalLaw>(contact, ModifiedThermalLaw::Variant::Bow);
    case FrictionModel::ModifiedRod:
        return std::make_unique<ModifiedThermalLaw>(contact, ModifiedThermalLaw::Variant::Rod);
    }
    throw std::invalid_argument("unknown FrictionModel value");
}

} // namespace rosin::physics
