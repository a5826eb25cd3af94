#include "cli/ScanCommand.h"

#include "cli/CommandLine.h"
#include "cli/HelpPage.h"
#include "cli/ScanCompareCommand.h"
#include "cli/ScanOptions.h"
#include "lab/scan/Merge.h"
#include "lab/scan/ScanRun.h"
#include "lab/scan/StopSignal.h"
#include "lab/scan/WorkerPool.h"
#ifdef ROSIN_WITH_MPI
#include "lab/scan/mpi/MpiScan.h"
#endif

namespace rosin::cli
{

namespace
{
// Exit status of a run stopped by a signal, as a shell reports a process killed by it.
int stoppedStatus()
{
    return 128 + (scan::stopSignal() != 0 ? scan::stopSignal() : 2);
}

void describe(const ScanCommandLine& c, std::ostream& out)
{
    const auto& s = c.spec;
    out << "scan " << scan::kindName(s.kind) << ": preset " << s.model.preset << ", string "
        << s.model.string.name << ", body " << s.model.body << ", friction " << s.model.friction << "; "
        << s.betas.size() << " beta(s) x " << s.forces.size() << " forces x " << s.second.size()
        << (s.kind == scan::ScanKind::Guettler ? " accelerations" : " bow speed") << " = " << s.cellCount()
        << " cells of " << s.trialSeconds << " s at " << s.sampleRate << " Hz";
    if (c.run.shard)
        out << "; shard " << c.run.shard->index << "/" << c.run.shard->count;
    out << "; " << (c.run.threads > 0 ? c.run.threads : scan::defaultThreadCount()) << " thread(s)"
        << (c.mpi ? " per MPI rank" : "") << "\n";
}

int runMpi([[maybe_unused]] const ScanCommandLine& c, [[maybe_unused]] std::ostream& out,
           [[maybe_unused]] std::ostream& err)
{
#ifdef ROSIN_WITH_MPI
    const scan::MpiRunReport r = scan::runScanMpi(c.spec, c.out, c.run, out, err);
    if (r.root)
    {
        out << "computed on " << r.ranks << " MPI rank(s)\n";
        return r.report.complete ? kExitOk : stoppedStatus();
    }
    return scan::stopSignalled() ? stoppedStatus() : kExitOk;
#else
    throw UsageError("--mpi: this rosin was built without MPI (configure with -DROSIN_WITH_MPI=ON and an MPI "
                     "library, e.g. Debian's libopenmpi-dev)");
#endif
}
} // namespace

HelpPage scanHelpPage()
{
    HelpPage page;
    page.command = "scan";
    page.usage = {"rosin scan schelleng [options] --out DIR", "rosin scan guettler [options] --out DIR",
                  "rosin scan merge DIR [--no-figures]", "rosin scan compare A B --out DIR"};
    page.subcommands = {"schelleng", "guettler", "merge", "compare"};
    page.sections = {
        {"",
         R"(Playability diagrams of one bowed string ([Galluzzo2017] sections 3.1-3.3), one simulated trial per
grid cell:
  schelleng  steady bowing at one speed over (beta, force), both log-spaced; the regime at the end of each
             trial (Helmholtz, S-motion, double/multiple slipping, raucous, ALF, constant slipping, no slip).
             The bow reaches its speed with constant acceleration over --ramp, then holds it.
  guettler   constant-acceleration starts from rest (v = a t, not capped) over (force, acceleration),
             linearly spaced, at each beta: periods from the first slip to lasting Helmholtz motion
             (judged over the first 40 periods; empty = not within 20), mu_s and the jump at the first
             slip, the failure type, and the regime at the end.
  merge      joins the shards of a scan split with --shard into its files.
  compare    draws the difference of two finished scans of one kind and grid (DIR/compare.png).
Writes DIR/scan.csv (one row per cell), DIR/scan.json (summary: Helmholtz share, fitted Schelleng
boundaries, theory lines) and the figures of Source/lab/figures/plot_scan.py (python3 with matplotlib);
see the manual's scan-format page.
)"},
        {"", "", &scanOptionTable()},
        {"compare", "", &scanCompareOptionTable()},
        {"",
         R"(A run appends every finished cell to DIR/scan.partial.csv; after Ctrl-C (or SIGTERM) the running cells
finish, and the same command resumes without recomputing them. The files are byte-identical however the
work is split (threads, resume, shards, MPI). A partial file of a different scan is refused.
)"},
    };
    page.examples = {
        "rosin scan schelleng --friction classical --out schelleng-classical",
        "rosin scan guettler --friction plastic --beta 0.0899 --grid 20 --out guettler-plastic",
        "rosin scan guettler --beta 0.0899 --grid 300 --shard 3/16 --out big && rosin scan merge big",
        "mpirun -np 4 rosin scan guettler --mpi --threads 2 --out guettler-all",
    };
    page.exitStatus = "0 success, 1 bad value, preset or folder, 2 usage error, 128+signal when stopped";
    return page;
}

std::string scanHelp()
{
    return helpText(scanHelpPage());
}

void checkScanArguments(const std::vector<std::string>& args)
{
    if (!args.empty() && args.front() == "compare")
        parseScanCompare({args.begin() + 1, args.end()});
    else
        parseScanCommandLine(args);
}

int runScan(const std::vector<std::string>& args, std::ostream& out, std::ostream& err)
{
    if (!args.empty() && args[0] == "compare")
        return runScanCompare({args.begin() + 1, args.end()}, out, err);
    const ScanCommandLine c = parseScanCommandLine(args);
    if (c.action == ScanCommandLine::Action::Help)
    {
        out << scanHelp();
        return kExitOk;
    }
    scan::installStopSignals();
    if (c.action == ScanCommandLine::Action::Merge)
    {
        scan::mergeShards(c.out, c.run.output, out, err);
        return kExitOk;
    }
    if (c.mpi)
        return runMpi(c, out, err);
    describe(c, out);
    const scan::RunReport report = scan::runScan(c.spec, c.out, c.run, out, err);
    return report.complete ? kExitOk : stoppedStatus();
}

} // namespace rosin::cli
