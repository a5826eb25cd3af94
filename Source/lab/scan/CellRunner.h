#pragma once
// Runs cells of one scan, up to kLanes cells of one beta at a time in the SIMD lanes of one VoiceLanes.
// Preparing a thermal law calibrates it (~25 ms, longer than a 0.5 s trial), so each worker prepares one
// voice and the lanes' friction once (physics::makeLaneFriction) and resets them between batches: reset()
// returns the string, body and friction to rest, so a cell's result depends neither on which cells the
// runner computed before nor on which cells share its batch (tests/scan checks both byte for byte).
#include <array>
#include <cstddef>
#include <vector>

#include "CellResult.h"
#include "ScanSpec.h"
#include "physics/lanes/VoiceLanes.h"
#include "physics/voice/BowedStringVoice.h"

namespace rosin::scan
{

class CellRunner
{
  public:
    explicit CellRunner(const ScanSpec& spec);
    CellRunner(const CellRunner&) = delete;
    CellRunner& operator=(const CellRunner&) = delete;

    /// Cells that can share a batch: the same beta, at most kLanes of them.
    static constexpr std::size_t kBatch = physics::kLanes;
    /// Computes 1..kBatch cells of one beta together; results in the order given.
    std::vector<CellResult> run(const std::vector<std::size_t>& cells);
    CellResult run(std::size_t cell) { return run(std::vector<std::size_t>{cell}).front(); }
    /// The per-sample output of a cell of the last run, by its position in that run (tests, further
    /// analyses).
    const std::vector<physics::VoiceSample>& lastSamples(std::size_t position = 0) const noexcept
    {
        return samples_[position];
    }
    double periodSamples() const noexcept { return periodSamples_; }

  private:
    void useBeta(double beta);

    const ScanSpec& spec_;
    physics::BowedStringVoice voice_; ///< holds the discrete system for the current beta
    physics::VoiceLanes lanes_;
    double lanesBeta_ = -1.0;
    std::array<std::vector<physics::VoiceSample>, physics::kLanes> samples_;
    double periodSamples_ = 0.0;
};

/// Splits a list of cells into runs of consecutive cells with the same beta, at most kBatch long.
std::vector<std::vector<std::size_t>> batchesOf(const ScanSpec& spec, const std::vector<std::size_t>& cells);

} // namespace rosin::scan
