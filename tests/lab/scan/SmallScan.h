#pragma once
// A small, quick scan for the tests of the run machinery: Guettler, classical law (no calibration to wait
// for), two betas x 3 forces x 4 accelerations = 24 cells of 60 ms.
#include <sstream>
#include <string>

#include "lab/scan/Axis.h"
#include "lab/scan/RunFiles.h"
#include "lab/scan/ScanRun.h"
#include "lab/scan/ScanSpec.h"

namespace rosin::scan::test
{

inline ScanSpec smallSpec()
{
    ScanSpec s = defaultSpec(ScanKind::Guettler);
    s.model.friction = "classical";
    s.trialSeconds = 0.06;
    s.betas = {0.0899, 0.1428};
    s.forces = linearAxis(0.6, 2.0, 3);
    s.second = linearAxis(0.5, 3.0, 4);
    return s;
}

inline RunOptions quietOptions(unsigned threads = 2)
{
    RunOptions o;
    o.threads = threads;
    o.output.figures = false;
    o.progress = false;
    return o;
}

/// Runs the scan with its reports discarded.
inline RunReport run(const ScanSpec& spec, const std::string& dir, const RunOptions& options)
{
    std::ostringstream out, err;
    return runScan(spec, dir, options, out, err);
}

} // namespace rosin::scan::test
