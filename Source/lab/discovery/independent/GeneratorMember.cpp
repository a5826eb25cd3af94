#include "lab/discovery/independent/GeneratorMember.h"

#include "lab/discovery/independent/IndependentStreams.h"

namespace rosin::discovery
{

GeneratorMember generatorMember(unsigned number)
{
    GeneratorMember m;
    m.number = number;
    if (number == 0)
        return m;
    SeededRandom r(number, independent_streams::kMember);
    auto pick = [&r](int a, int b, int c)
    {
        const double u = r.uniform();
        return u < 1.0 / 3.0 ? a : u < 2.0 / 3.0 ? b : c;
    };
    m.oversampling = pick(2, 3, 4);
    m.lossFitHarmonic = r.uniform(24.0, 48.0);
    m.dispersionFitTopHz = r.uniform(7000.0, 12000.0);
    m.heatSurfaceCell = r.uniform(0.3, 0.8);
    m.heatGridGrowth = r.uniform(1.15, 1.4);
    m.advectionWidth = r.uniform(0.8, 1.25);
    m.torsionalWaveSpeed = r.uniform(0.95, 1.05);
    m.torsionalQ = r.uniform(0.8, 1.25);
    m.torsionalImpedance = r.uniform(0.9, 1.1);
    m.antiAliasOrder = pick(2, 4, 6);
    m.body = r.uniform() < 0.75;
    return m;
}

physics::StringParameters GeneratorMember::torsionOf(physics::StringParameters string) const
{
    string.torsionalWaveSpeed *= torsionalWaveSpeed;
    string.torsionalQ *= torsionalQ;
    string.torsionalImpedance *= torsionalImpedance;
    return string;
}

void applyMemberRig(const GeneratorMember& member, config::Preset& preset)
{
    if (!member.body)
        preset.body = "rigid";
}

std::vector<std::pair<std::string, double>> GeneratorMember::values() const
{
    return {{"member", static_cast<double>(number)},
            {"oversampling", static_cast<double>(oversampling)},
            {"lossFitHarmonic", lossFitHarmonic},
            {"dispersionFitTopHz", dispersionFitTopHz},
            {"heatSurfaceCell", heatSurfaceCell},
            {"heatGridGrowth", heatGridGrowth},
            {"advectionWidth", advectionWidth},
            {"torsionalWaveSpeed", torsionalWaveSpeed},
            {"torsionalQ", torsionalQ},
            {"torsionalImpedance", torsionalImpedance},
            {"antiAliasOrder", static_cast<double>(antiAliasOrder)},
            {"body", body ? 1.0 : 0.0}};
}

} // namespace rosin::discovery
