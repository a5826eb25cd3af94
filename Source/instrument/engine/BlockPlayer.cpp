#include "instrument/engine/BlockPlayer.h"

namespace rosin::engine
{

namespace
{
// Each sample through the output stage into the block's output.
class ToOutputStage final : public performer::SampleSink
{
  public:
    ToOutputStage(OutputStage& stage, const OutputSettings& settings, float* out) noexcept
        : stage_(stage), settings_(settings), out_(out)
    {
    }
    void take(int i, const physics::BowedInstrument& instrument, double bridgeForce) noexcept override
    {
        bool bad = false;
        out_[i] = stage_.sample(i, instrument, bridgeForce, settings_, bad);
        nonFinite += bad ? 1 : 0;
    }
    int nonFinite = 0;

  private:
    OutputStage& stage_;
    const OutputSettings& settings_;
    float* out_;
};
} // namespace

void BlockPlayer::prepare(const Engine& engine, double sampleRate, int maximumBlockSize)
{
    performer_.prepare(engine.serial, engine.openFrequencies.data(), engine.instrument.stringCount(),
                       sampleRate);
    performer_.setForceShares(engine.forceShares.data(), engine.instrument.stringCount());
    performer_.setBands(engine.bands.data(), engine.instrument.stringCount());
    output_.prepare(sampleRate, kGainSmoothingSeconds, maximumBlockSize);
}

void BlockPlayer::follow(const Engine& engine) noexcept
{
    performer_.follow(engine.serial, engine.openFrequencies.data(), engine.instrument.stringCount(),
                      engine.sampleRate);
    performer_.setForceShares(engine.forceShares.data(), engine.instrument.stringCount());
    performer_.setBands(engine.bands.data(), engine.instrument.stringCount());
}

void BlockPlayer::reset(Engine& engine) noexcept
{
    engine.instrument.reset();
    performer_.reset();
    output_.reset();
}

BlockPlayer::BlockResult BlockPlayer::play(Engine& engine, performer::EventSource& events,
                                           const OutputSettings& output, float* out, int n) noexcept
{
    ToOutputStage sink(output_, output, out);
    BlockResult result;
    result.runawayResets = performer_.process(engine.instrument, events, sink, n);
    output_.finishBlock(out, n, output);
    result.nonFinite = sink.nonFinite;
    return result;
}

} // namespace rosin::engine
