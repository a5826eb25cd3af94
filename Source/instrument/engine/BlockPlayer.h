#pragma once
// One block of the instrument as a front end plays it: the performer (events and the block's parameters ->
// gesture -> instrument, sample by sample) and the output stage (the chosen quantity, its measured response,
// gain, guards). The plugin's processor and the offline render both play through it, so what they output is
// the same for the same events and parameters.
//
// Real-time contract: prepare() allocates; everything else never allocates, locks or makes a system call.
#include "instrument/engine/Engine.h"
#include "instrument/engine/EngineParameters.h"
#include "instrument/engine/OutputStage.h"
#include "instrument/performer/Performer.h"

namespace rosin::engine
{

/// Smoothing of the output level, s.
inline constexpr double kGainSmoothingSeconds = 0.01;

class BlockPlayer
{
  public:
    /// Off the audio thread: the performer for `engine`'s strings, the output stage for blocks of up to
    /// `maximumBlockSize` samples. A measured response handed to output().measured() before is built here.
    void prepare(const Engine& engine, double sampleRate, int maximumBlockSize);
    /// No engine any more (the next follow() prepares the gesture whatever the strings).
    void release() noexcept { performer_.release(); }

    /// At a block's start: the engine it plays (a rebuilt one keeps the gesture going).
    void follow(const Engine& engine) noexcept;
    /// The engine's instrument, the gesture and the output stage back to rest.
    void reset(Engine& engine) noexcept;
    /// The block's parameters, before its events.
    void beginBlock(const ParameterSnapshot& snapshot) noexcept
    {
        performer_.beginBlock({snapshot.gesture, snapshot.intonationByEar});
    }

    struct BlockResult
    {
        int runawayResets = 0; ///< strings that reset themselves after a runaway
        int nonFinite = 0;     ///< samples whose quantity was not finite (written as 0)
    };
    /// n samples of `engine` with `events` into out[0..n), through the output stage with `output`.
    BlockResult play(Engine& engine, performer::EventSource& events, const OutputSettings& output, float* out,
                     int n) noexcept;

    performer::Performer& performer() noexcept { return performer_; }
    const performer::Performer& performer() const noexcept { return performer_; }
    OutputStage& output() noexcept { return output_; }

  private:
    performer::Performer performer_;
    OutputStage output_;
};

} // namespace rosin::engine
