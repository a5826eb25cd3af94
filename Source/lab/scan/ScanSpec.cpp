#include "lab/scan/ScanSpec.h"

#include "lab/scan/Axis.h"

namespace rosin::scan
{

const char* classificationName(Classification c) noexcept
{
    return c == Classification::BridgeForce ? "bridge-force" : "state";
}

const char* kindName(ScanKind kind) noexcept
{
    return kind == ScanKind::Schelleng ? "schelleng" : "guettler";
}

const char* trialEndName(GuettlerTrialEnd end) noexcept
{
    switch (end)
    {
    case GuettlerTrialEnd::Whole:
        return "whole";
    case GuettlerTrialEnd::AfterWindow:
        return "window";
    case GuettlerTrialEnd::WhenDecided:
        return "decided";
    }
    return "decided";
}

const std::vector<double>& seedGuettlerBetas()
{
    static const std::vector<double> betas = {0.0357, 0.0449, 0.0566, 0.0714, 0.0899, 0.1133, 0.1428, 0.18};
    return betas;
}

ScanSpec defaultSpec(ScanKind kind)
{
    ScanSpec s;
    s.kind = kind;
    s.model = modelFromPreset(config::defaultPreset());
    if (kind == ScanKind::Schelleng)
    {
        s.trialSeconds = 1.0;
        s.rampSeconds = 0.1;
        s.betas = logAxis(0.02, 0.18, 20);
        s.forces = logAxis(0.1, 3.0, 20);
        s.second = {0.05};
    }
    else
    {
        s.trialSeconds = 0.5;
        s.rampSeconds = 0.0;
        s.betas = seedGuettlerBetas();
        s.forces = linearAxis(0.4, 3.2, 20);
        s.second = linearAxis(0.08, 3.2, 20);
    }
    return s;
}

CellCoordinates coordinatesOf(const ScanSpec& spec, std::size_t cell)
{
    const std::size_t nForce = spec.forces.size(), nSecond = spec.second.size();
    return {cell / (nForce * nSecond), (cell / nSecond) % nForce, cell % nSecond};
}

std::size_t cellIndex(const ScanSpec& spec, const CellCoordinates& c)
{
    return (c.beta * spec.forces.size() + c.force) * spec.second.size() + c.second;
}

CellSettings cellSettings(const ScanSpec& spec, std::size_t cell)
{
    const CellCoordinates c = coordinatesOf(spec, cell);
    return {cell, spec.betas[c.beta], spec.forces[c.force], spec.second[c.second]};
}

} // namespace rosin::scan
