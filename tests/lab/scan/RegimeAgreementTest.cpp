// The regime classifier from the simulation's state (flybacks) against the classifier from the bridge force
// alone, as a measurement would give, over a 10 x 10 Schelleng scan (classical curve, cello D3 on the body):
// the lab's specification asks for agreement on at least 90 % of the cells. Both judge the same window: the
// second half of the time after the bow reached its speed.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <string>

#include "core/analysis/RegimeClassifier.h"
#include "lab/scan/Axis.h"
#include "lab/scan/CellRunner.h"
#include "lab/scan/ScanSpec.h"
#include "lab/scan/TrialProtocol.h"

namespace rosin::scan
{
namespace ROSIN_FILE_LOCAL
{

TEST(RegimeAgreement, StateAndBridgeForceAgreeOverASchellengScan)
{
    ScanSpec spec = defaultSpec(ScanKind::Schelleng);
    spec.model.friction = "classical";
    spec.trialSeconds = 0.6;
    spec.forces = logAxis(0.1, 3.0, 10);
    spec.betas = logAxis(0.02, 0.18, 10);
    CellRunner runner(spec);
    int agree = 0, cells = 0;
    std::map<std::string, int> disagreements;
    for (std::size_t cell = 0; cell < spec.cellCount(); ++cell)
    {
        runner.run(cell);
        const auto& samples = runner.lastSamples();
        const TrialProtocol protocol(spec, cellSettings(spec, cell));
        const std::size_t begin = protocol.rampEnd() + (samples.size() - protocol.rampEnd()) / 2;
        const analysis::AnalysisWindow window{begin, samples.size()};
        std::vector<double> force(samples.size());
        for (std::size_t k = 0; k < samples.size(); ++k)
            force[k] = samples[k].bridgeForce;
        const auto fromState = analysis::classifyFromVoice(samples, runner.periodSamples(), window).regime;
        const auto fromForce =
            analysis::classifyFromBridgeForce(force, runner.periodSamples(), window).regime;
        ++cells;
        if (fromState == fromForce)
            ++agree;
        else
            ++disagreements[std::string(analysis::regimeName(fromState)) + " -> " +
                            std::string(analysis::regimeName(fromForce))];
    }
    std::string detail;
    for (const auto& [pair, n] : disagreements)
        detail += " " + pair + " x" + std::to_string(n) + ";";
    std::printf(
        "[figure] regime from state vs from bridge force alone, 10 x 10 Schelleng (classical): %d of %d "
        "cells agree (%.0f %%); disagreements:%s\n",
        agree, cells, 100.0 * agree / cells, detail.c_str());
    EXPECT_GE(agree, 90 * cells / 100);
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::scan
