#pragma once
// Runs cells of one scan in the SIMD lanes of one VoiceLanes: kLanes trials of one beta at a time, each lane
// taking the next cell as soon as its trial ends (TrialEnd.h), so no lane waits for a longer batch-mate. A
// Guettler trial with an exact friction law starts where it is certain to still stick to the bow, scaled from
// a unit-acceleration start (physics::RampStart).
// Preparing a thermal law calibrates it (~25 ms, longer than a 0.5 s trial), so each worker prepares one
// voice and the lanes' friction once (physics::makeLaneFriction) and returns a lane to rest before each
// cell: a cell's result depends neither on which cells the runner computed before nor on which cells ran
// beside it (tests/lab/scan/ checks both byte for byte).
#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

#include "core/physics/lanes/RampStart.h"
#include "core/physics/lanes/VoiceLanes.h"
#include "core/physics/voice/BowedStringVoice.h"
#include "lab/scan/CellResult.h"
#include "lab/scan/ScanSpec.h"

namespace rosin::scan
{

class CellRunner
{
  public:
    /// skipStuckStarts: Guettler trials of an exact law skip the samples in which they certainly still stick
    /// (physics::RampStart); false computes every sample (tests compare the two).
    explicit CellRunner(const ScanSpec& spec, bool skipStuckStarts = true);
    CellRunner(const CellRunner&) = delete;
    CellRunner& operator=(const CellRunner&) = delete;

    static constexpr std::size_t kBatch = physics::kLanes;
    /// The next cell to run, or none when there are no more.
    using CellSource = std::function<std::optional<std::size_t>()>;
    using CellSink = std::function<void(const CellResult&)>;
    /// Runs cells from `next` until it has none, each result to `done` as its trial ends (not in order).
    /// Cells of another beta than the lanes' wait until every lane is free.
    void runAll(const CellSource& next, const CellSink& done);
    /// Computes cells of one beta; results in the order given.
    std::vector<CellResult> run(const std::vector<std::size_t>& cells);
    CellResult run(std::size_t cell) { return run(std::vector<std::size_t>{cell}).front(); }
    /// The per-sample output of a cell of the last run() of at most kBatch cells, by its position in that run
    /// (tests, further analyses).
    const std::vector<physics::VoiceSample>& lastSamples(std::size_t position = 0) const noexcept
    {
        return samples_[position];
    }
    double periodSamples() const noexcept { return periodSamples_; }

  private:
    struct Lane;
    using Lanes = std::array<Lane, physics::kLanes>;
    bool fillFreeLanes(Lanes& lanes, const CellSource& next, std::optional<std::size_t>& waiting, bool& more);
    void stepLanes(Lanes& lanes, const CellSink& done);
    void useBeta(double beta);
    void start(Lane& lane, std::size_t cell);
    void skipStuckStart(Lane& lane, std::vector<physics::VoiceSample>& samples);
    CellResult finish(const Lane& lane) const;

    const ScanSpec& spec_;
    physics::BowedStringVoice voice_; ///< holds the discrete system for the current beta
    physics::VoiceLanes lanes_;
    double lanesBeta_ = -1.0;
    bool skipStuckStarts_ = false;
    physics::RampStart rampStart_;
    std::array<std::vector<physics::VoiceSample>, physics::kLanes> samples_;
    double periodSamples_ = 0.0;
};

} // namespace rosin::scan
