#include "ScanCommand.h"

#include "CommandLine.h"
#include "ScanCompareCommand.h"
#include "ScanOptions.h"
#include "scan/Merge.h"
#include "scan/ScanRun.h"
#include "scan/StopSignal.h"
#include "scan/WorkerPool.h"
#ifdef ROSIN_WITH_MPI
#include "scan/mpi/MpiScan.h"
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

std::string scanHelp()
{
    return R"(usage: rosin scan schelleng [options] --out DIR
       rosin scan guettler  [options] --out DIR
       rosin scan merge DIR [--no-figures]
       rosin scan compare A B --out DIR     the difference of two scans (DIR/compare.png)

Playability diagrams of one bowed string (seed 001 sections 3.1-3.3), one simulated trial per grid cell:
  schelleng  steady bowing at one speed over (beta, force), both log-spaced; the regime at the end of each
             trial (Helmholtz, S-motion, double/multiple slipping, raucous, ALF, constant slipping, no slip).
             The bow reaches its speed with constant acceleration over --ramp, then holds it.
  guettler   constant-acceleration starts from rest (v = a t, not capped) over (force, acceleration),
             linearly spaced, at each beta: periods from the first slip to lasting Helmholtz motion
             (judged over the first 40 periods; empty = not within 20), mu_s and the jump at the first
             slip, the failure type, and the regime at the end.
Writes DIR/scan.csv (one row per cell), DIR/scan.json (summary: Helmholtz share, fitted Schelleng
boundaries, theory lines) and the figures of Source/lab/figures/plot_scan.py (python3 with matplotlib);
see Resources/docs/scan-format.md.

model:
  --preset NAME|FILE.json  instrument preset (default galluzzo-rig: cello D3 on the cello body, plastic)
  --friction LAW           classical, reconstructed, plastic, viscous, modified-bow, modified-rod
  --sample-rate HZ         integer 8000..384000 (default 48000)
variations (seed 001 Figs. 9-12):
  --layer-thickness M      rosin layer of the steady-sliding (calibration) contact (default 10e-6; Fig. 9: 15e-6)
  --contact-radius M       radius of the calibration contact at 3 N (default 500e-6; Fig. 10: 700e-6)
  --contact coulomb|hertz  contact area ~ N (default) or ~ N^(2/3) (Fig. 11)
  --finger-damping         the string's intrinsic damping of a finger-stopped note (Fig. 12c)
  --rigid-bridge           no body: a rigid bridge (Fig. 12d)
  --no-torsion             no torsional modes (Fig. 12e)
  --no-stiffness           no bending stiffness (Fig. 12f)
grid (defaults: seed 001):
  --grid N | NxM           N forces x M betas (schelleng) or x M accelerations (guettler); each 1..300;
                           default 20x20
  --force-range A:B        N (default schelleng 0.1:3, guettler 0.4:3.2)
  --beta LIST              comma-separated betas (0.01..0.5); guettler default: the eight of Fig. 5,
                           0.0357,0.0449,0.0566,0.0714,0.0899,0.1133,0.1428,0.18
  --beta-range A:B         schelleng only (default 0.02:0.18)
  --acceleration-range A:B guettler only, m/s^2 (default 0.08:3.2)
  --bow-speed V            schelleng only, m/s (default 0.05)
trial:
  --duration S             seconds per trial (default schelleng 1, guettler 0.5)
  --ramp S                 schelleng only: time to reach the bow speed (default 0.1)
  --full-trials            guettler only: run every trial to --duration; by default a trial ends once its
                           transient is decided (44 periods after the first full flyback, or as soon as
                           Helmholtz motion can no longer start within 20 periods), and the regime column
                           is then that of the 20 periods before that point
  --classify state|bridge-force
                           how slips are found for the regime and the transient: from the solver's state
                           (default: full flybacks of the bowed point) or from the bridge force alone, as
                           seed 001 treats measured and simulated trials alike (guettler trials then end
                           with their transient window at the latest)
running:
  --out DIR                output folder (required; created if missing)
  --threads N              threads (default: every core)
  --shard K/N              compute only the cells with index % N == K (Slurm arrays: K = $SLURM_ARRAY_TASK_ID);
                           writes DIR/scan.shard-K-of-N.csv; then: rosin scan merge DIR
  --mpi                    under mpirun -np R: cells spread over the ranks, rank 0 writes the files
  --no-figures             do not run the figure script
  --no-progress            no progress line on stderr
  -h, --help               this text

A run appends every finished cell to DIR/scan.partial.csv; after Ctrl-C (or SIGTERM) the running cells
finish, and the same command resumes without recomputing them. The files are byte-identical however the
work is split (threads, resume, shards, MPI). A partial file of a different scan is refused.

examples:
  rosin scan schelleng --friction classical --out schelleng-classical
  rosin scan guettler --friction plastic --beta 0.0899 --grid 20 --out guettler-plastic
  rosin scan guettler --beta 0.0899 --grid 300 --shard 3/16 --out big && rosin scan merge big
  mpirun -np 4 rosin scan guettler --mpi --threads 2 --out guettler-all

exit status: 0 success, 1 bad value, preset or folder, 2 usage error, 128+signal when stopped
)";
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
