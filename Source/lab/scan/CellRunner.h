#pragma once
// Runs cells of one scan on one prepared voice. Preparing a thermal law calibrates it (~25 ms, longer than a
// 0.5 s trial), so each worker prepares one voice and resets it between cells: reset() returns the string,
// body and friction law to rest, and the bow position is reapplied on the first sample, so a cell's result
// does not depend on which cells the runner computed before (tests/scan checks this byte for byte).
#include <cstddef>
#include <vector>

#include "CellResult.h"
#include "ScanSpec.h"
#include "physics/voice/BowedStringVoice.h"

namespace rosin::scan
{

class CellRunner
{
  public:
    explicit CellRunner(const ScanSpec& spec);
    CellRunner(const CellRunner&) = delete;
    CellRunner& operator=(const CellRunner&) = delete;

    CellResult run(std::size_t cell);
    /// The per-sample output of the last run (analyses beyond the scan's row, e.g. tests).
    const std::vector<physics::VoiceSample>& lastSamples() const noexcept { return samples_; }
    double periodSamples() const noexcept { return periodSamples_; }

  private:
    const ScanSpec& spec_;
    physics::BowedStringVoice voice_;
    std::vector<physics::VoiceSample> samples_;
    double periodSamples_ = 0.0;
};

} // namespace rosin::scan
