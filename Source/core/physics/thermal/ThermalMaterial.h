#pragma once
// The thermal properties of one solid, and the solids of Rosin's contacts ([Notes §2.3a], §2.7).
// These are handbook values, not fitted to any result of the source texts: [Galluzzo2017] (Table 2 caption)
// took its values from Table 1 of [Woodhouse2003], which the project could not obtain ([Notes §10] Q2), so
// each solid gets the middle of the range the literature gives for its material, with the source beside it.
// What follows from them ([Woodhouse-thermal]'s crossing temperatures, [Smith2000]'s stick-slip frequency and
// contact temperatures) is a prediction, reported in Resources/docs/physics.md, "The source texts, checked".
// Rosin's heat capacity is the one constant [Smith2000] calls uncertain: RosinMaterial.h offers a calibrated
// one.
#include <cmath>

namespace rosin::physics
{

/// Conductivity and volumetric heat capacity of one solid.
struct ThermalMaterial
{
    double conductivity = 0.15;             ///< K, W/(m K)
    double volumetricHeatCapacity = 1.73e6; ///< rho c, J/(m^3 K)
    /// Thermal effusivity e = sqrt(K rho c), W s^1/2 / (m^2 K): what sets 1-D conduction at short times.
    double effusivity() const noexcept { return std::sqrt(conductivity * volumetricHeatCapacity); }
    /// Diffusivity kappa = K / (rho c), m^2/s.
    double diffusivity() const noexcept { return conductivity / volumetricHeatCapacity; }
};

namespace materials
{
/// Rosin (colophony): density 1080 kg/m^3 (specific gravity ~1.08: CAMEO Materials Database; O'Reilly,
/// Dictionary of Oil, "rosin"); K 0.15 W/(m K) and c 1.6 kJ/(kg K), the middle of the ranges of amorphous
/// natural resins (0.1-0.2 W/(m K), 1.0-1.8 kJ/(kg K); [Notes §2.7]).
inline constexpr ThermalMaterial rosin{0.15, 1080.0 * 1600.0};
/// PMMA (acrylic, "perspex"): K 0.19 W/(m K), density 1190 kg/m^3, c 1.42 kJ/(kg K) (polymer handbook
/// values; manufacturers' data sheets give 0.17-0.21 W/(m K) and 1.4-1.47 kJ/(kg K)).
inline constexpr ThermalMaterial acrylic{0.19, 1190.0 * 1420.0};
/// Soda-lime glass: K 1.0 W/(m K), density 2500 kg/m^3, c 0.8 kJ/(kg K) ([Notes §2.7], textbook).
inline constexpr ThermalMaterial glass{1.0, 2500.0 * 800.0};
/// Wood across the grain (a hardwood dowel): K 0.16 W/(m K), density 700 kg/m^3, c 1.25 kJ/(kg K) (wood
/// handbook ranges: 0.1-0.2 W/(m K) across the grain for specific gravity 0.4-0.8; c ~1.2-1.4 kJ/(kg K) dry
/// at room temperature).
inline constexpr ThermalMaterial wood{0.16, 700.0 * 1250.0};
/// Steel: K 50 W/(m K), density 7850 kg/m^3, c 470 J/(kg K) ([Notes §2.7], textbook). Listed for
/// comparison: a bare steel surface is ~30x the effusivity of rosin.
inline constexpr ThermalMaterial steel{50.0, 7850.0 * 470.0};
} // namespace materials

/// The three bodies the contact's heat goes into ([Smith2000]: "conduction into the two neighbouring solids,
/// convection ... and absorption in the contact volume"; [Notes §2.3a]).
struct ContactMaterials
{
    /// The softened rosin layer itself: its capacity and the rosin advected through the contact.
    ThermalMaterial layer = materials::rosin;
    /// The solid the contact stays on (the string, [Smith2000]'s wedge). A played string carries rosin, and
    /// it is taken as rosin here [A]: with it, prescribed Helmholtz sliding gives the ~50 K mean rise
    /// [Euphonics] 9.6 reports for the original model ([Notes §2.6b]); a bare steel surface would hold the
    /// rise to a few kelvin.
    ThermalMaterial stationary = materials::rosin;
    /// The solid that slides through the contact (the rod or the bow hair). Galluzzo's rod: acrylic with a
    /// rubbed-on rosin film ([Galluzzo2017] §2.1, "the low thermal conductivity of acrylic allows this").
    ThermalMaterial moving = materials::acrylic;
    /// Advection width w = ratio x a. [Smith2000]: once the layer shears uniformly, the rosin's volume flow
    /// through the contact halves, so a disc of width 2a passes rho c (2a / 2) delta |dv|: ratio 1.
    double advectionWidthRatio = 1.0;
};

} // namespace rosin::physics
