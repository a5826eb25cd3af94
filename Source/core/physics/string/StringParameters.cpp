#include "core/physics/string/StringParameters.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace rosin::physics
{

double StringParameters::waveSpeed() const
{
    return std::sqrt(tension / massPerLength);
}
double StringParameters::impedance() const
{
    return std::sqrt(tension * massPerLength);
}
double StringParameters::fundamental() const
{
    return waveSpeed() / (2.0 * length);
}

double StringParameters::inharmonicity(double vibratingLength) const
{
    return std::numbers::pi * std::numbers::pi * bendingStiffness /
           (tension * vibratingLength * vibratingLength);
}

double StringParameters::modeAngularFrequency(int n, double vibratingLength) const
{
    const double k = n * std::numbers::pi / vibratingLength;
    return std::sqrt((tension * k * k + bendingStiffness * k * k * k * k) / massPerLength);
}

double StringParameters::lossFactor(int n, double vibratingLength, bool stopped) const
{
    const double k = n * std::numbers::pi / vibratingLength;
    const double omega = modeAngularFrequency(n, vibratingLength);
    const double bending = bendingStiffness * k * k;
    return (tension * (etaF(stopped) + etaA() / omega) + bending * etaB()) / (tension + bending);
}

namespace
{
// Tension and mass per length fix the open pitch: m = P / (2 L f0)^2.
double massFor(double tension, double length, double f0)
{
    return tension / std::pow(2.0 * length * f0, 2.0);
}

StringParameters make(std::string name, double f0, double tension, double length, double EI, double lossF,
                      double lossB, double lossA, double ctOverC, double ZtOverZ0, double Qt,
                      std::string source)
{
    StringParameters s;
    s.name = std::move(name);
    s.tension = tension;
    s.length = length;
    s.massPerLength = massFor(tension, length, f0);
    s.bendingStiffness = EI;
    s.lossF = lossF;
    s.stoppedLossF = 3.0 * lossF; // [Galluzzo2017] Table 1: 23 -> 69 for the stopped cello D
    s.lossB = lossB;
    s.lossA = lossA;
    s.torsionalWaveSpeed = ctOverC * s.waveSpeed();
    s.torsionalImpedance = ZtOverZ0 * s.impedance();
    s.torsionalQ = Qt;
    s.source = std::move(source);
    return s;
}

std::vector<StringParameters> catalogue()
{
    std::vector<StringParameters> c;
    // [Galluzzo2017] Table 1, Galluzzo rig: open cello D3 ("Dominant"). Length from L = c / (2 f0).
    StringParameters d3;
    d3.name = "cello-D3";
    d3.tension = 111.0;
    d3.massPerLength = 2.7e-3;
    d3.length = std::sqrt(111.0 / 2.7e-3) / (2.0 * 146.8);
    d3.source = "[Galluzzo2017] Table 1 (Galluzzo rig); length from c/(2 f0)";
    c.push_back(d3);
    // [Galluzzo2017] Table 1, Schumacher rig: steel violin E string on a monochord, 693 Hz.
    StringParameters e5;
    e5.name = "violin-E5";
    e5.tension = 72.5;
    e5.massPerLength = 0.42e-3;
    e5.length = std::sqrt(72.5 / 0.42e-3) / (2.0 * 693.0);
    e5.bendingStiffness = 0.47e-4;
    e5.lossF = 5.0;
    e5.stoppedLossF = 15.0; // estimate: the cello ratio 69/23 applied to the violin E
    e5.lossB = 0.2;
    e5.lossA = 2.0;
    e5.torsionalWaveSpeed = 4620.0;
    e5.torsionalQ = 30.0;
    e5.torsionalImpedance = 0.61;
    e5.source = "[Galluzzo2017] Table 1 (Schumacher rig, 693 Hz monochord); stopped eta_F an estimate";
    c.push_back(e5);
    // The other strings: tensions are typical published values for medium-gauge synthetic-core strings
    // (manufacturers' tension charts give 105-145 N for cello, 40-75 N for violin); mass per length follows
    // from tension, length and pitch. Bending stiffness, losses and torsion are ESTIMATES scaled from the two
    // measured strings of [Galluzzo2017] (wound strings like the cello D, plain steel like the violin E).
    const double cello = 0.69, violin = 0.325;
    c.push_back(make("cello-C2", 65.41, 118.0, cello, 6.0e-4, 23, 12.5, 0.11, 3.7, 3.3, 45,
                     "estimate: tension typical chart value, EI/losses/torsion scaled from cello D3"));
    c.push_back(make("cello-G2", 98.00, 112.0, cello, 4.5e-4, 23, 12.5, 0.11, 3.7, 3.3, 45,
                     "estimate: tension typical chart value, EI/losses/torsion scaled from cello D3"));
    c.push_back(
        make("cello-A3", 220.0, 140.0, cello, 3.0e-4, 15, 6.0, 0.5, 5.0, 3.4, 40,
             "estimate: tension typical chart value, EI/losses/torsion between cello D3 and violin E5"));
    c.push_back(
        make("violin-G3", 196.0, 45.0, violin, 0.6e-4, 23, 12.5, 0.5, 3.7, 3.3, 45,
             "estimate: tension typical chart value, EI/losses/torsion scaled from cello D3 (wound)"));
    c.push_back(
        make("violin-D4", 293.7, 42.0, violin, 0.4e-4, 20, 8.0, 1.0, 4.0, 3.3, 40,
             "estimate: tension typical chart value, EI/losses/torsion scaled from cello D3 (wound)"));
    c.push_back(
        make("violin-A4", 440.0, 50.0, violin, 0.4e-4, 12, 3.0, 1.5, 6.0, 3.4, 35,
             "estimate: tension typical chart value, EI/losses/torsion between cello D3 and violin E5"));
    c.push_back(
        make("violin-E5-instrument", 659.26, 72.5, violin, 0.47e-4, 5, 0.2, 2.0, 11.1, 3.5, 30,
             "[Galluzzo2017] Table 1 violin E tension and losses, retuned to E5 = 659.26 Hz at L = 0.325 m"));
    return c;
}
} // namespace

std::vector<std::string> stringCatalogueNames()
{
    std::vector<std::string> names;
    for (const auto& s : catalogue())
        names.push_back(s.name);
    return names;
}

StringParameters stringFromCatalogue(const std::string& name)
{
    std::string known;
    for (const auto& s : catalogue())
    {
        if (s.name == name)
            return s;
        known += (known.empty() ? "" : ", ") + s.name;
    }
    throw std::invalid_argument("unknown string '" + name + "'; expected one of: " + known);
}

} // namespace rosin::physics
