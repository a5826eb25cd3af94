#include "lab/scan/Summary.h"

#include "lab/scan/BoundaryFit.h"
#include "lab/scan/CellAnalysis.h"
#include "lab/scan/Theory.h"
#include "lab/scan/Variations.h"

namespace rosin::scan
{

namespace
{
using nlohmann::json;

const char* secondName(ScanKind kind)
{
    return kind == ScanKind::Guettler ? "accelerations" : "bowSpeeds";
}

json theoryJson(const ScanSpec& spec)
{
    const Theory t = scanTheory(spec);
    json j = {{"Z0", t.Z0},
              {"bridgeResistance", t.bridgeResistance ? json(*t.bridgeResistance) : json(nullptr)},
              {"muStatic", t.friction.muStatic},
              {"muDynamic", t.friction.muDynamic},
              {"periodSeconds", t.periodSeconds}};
    if (spec.kind == ScanKind::Schelleng)
    {
        j["bowSpeed"] = spec.second.front();
        j["fmaxCoefficient"] = t.fmaxCoefficient;
        j["fminCoefficient"] = t.fminCoefficient;
        j["fminTotalCoefficient"] = t.fminTotalCoefficient;
        return j;
    }
    json wedge = json::array();
    for (const auto& w : t.wedge)
        wedge.push_back({{"beta", w.beta},
                         {"lowerAccelerationPerNewton", w.lowerAccelerationPerNewton},
                         {"upperAccelerationPerNewton", w.upperAccelerationPerNewton}});
    j["guettlerWedge"] = wedge;
    return j;
}

json fitJson(const std::optional<LineFit>& fit)
{
    if (!fit)
        return nullptr;
    return {{"slope", fit->slope}, {"intercept", fit->intercept}, {"points", fit->points}};
}

json perBetaJson(const ScanSpec& spec, const std::vector<CellResult>& results)
{
    json list = json::array();
    const std::size_t perBeta = spec.forces.size() * spec.second.size();
    for (std::size_t b = 0; b < spec.betas.size(); ++b)
    {
        std::size_t helmholtz = 0, reached = 0;
        for (std::size_t i = b * perBeta; i < (b + 1) * perBeta; ++i)
        {
            helmholtz += results[i].regime == analysis::Regime::Helmholtz ? 1 : 0;
            reached += results[i].transientPeriods ? 1 : 0;
        }
        list.push_back({{"beta", spec.betas[b]},
                        {"cells", perBeta},
                        {"helmholtzCells", helmholtz},
                        {"reachedCells", reached},
                        {"reachedFraction", static_cast<double>(reached) / static_cast<double>(perBeta)}});
    }
    return list;
}
} // namespace

std::vector<std::string> figureNames(ScanKind kind)
{
    if (kind == ScanKind::Schelleng)
        return {"schelleng.png", "mu-static.png", "jump.png"};
    return {"guettler.png", "mu-static.png", "jump.png"};
}

json scanSummary(const ScanSpec& spec, const std::vector<CellResult>& results)
{
    std::size_t helmholtz = 0, reached = 0;
    for (const auto& r : results)
    {
        helmholtz += r.regime == analysis::Regime::Helmholtz ? 1 : 0;
        reached += r.transientPeriods ? 1 : 0;
    }
    const double cells = static_cast<double>(results.size());
    json j = {
        {"format", "rosin-scan/1"},
        {"kind", kindName(spec.kind)},
        {"preset", spec.model.preset},
        {"friction", spec.model.friction},
        {"string", spec.model.string.name},
        {"body", spec.model.body},
        {"sampleRate", spec.sampleRate},
        {"trialSeconds", spec.trialSeconds},
        {"transientCapPeriods", kTransientCapPeriods},
        {"variations", variationsJson(spec.model)},
        {"grid", {{"betas", spec.betas}, {"forces", spec.forces}, {secondName(spec.kind), spec.second}}},
        {"cells", results.size()},
        {"helmholtzCells", helmholtz},
        {"helmholtzFraction", cells > 0 ? static_cast<double>(helmholtz) / cells : 0.0},
        {"theory", theoryJson(spec)},
        {"figures", figureNames(spec.kind)}};
    if (spec.kind == ScanKind::Schelleng)
    {
        j["rampSeconds"] = spec.rampSeconds;
        const HelmholtzEdges edges = helmholtzEdges(spec, results);
        j["boundaries"] = {{"upper", fitJson(fitLogLog(edges.upper))},
                           {"lower", fitJson(fitLogLog(edges.lower))}};
        return j;
    }
    j["reachedFraction"] = cells > 0 ? static_cast<double>(reached) / cells : 0.0;
    j["perBeta"] = perBetaJson(spec, results);
    return j;
}

} // namespace rosin::scan
