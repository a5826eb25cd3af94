// The performer without any host: events act at their sample whatever the block cut, an event stamped past
// its block's end is not lost, a rebuilt instrument with the same strings keeps the gesture going.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "instrument/performer/Performer.h"

namespace ROSIN_FILE_LOCAL
{
using namespace rosin;
using performer::Performer;
using player::GestureEvent;

constexpr double kRate = 48000.0;

// One block's events as a host hands them over: (stamp within the block, event), in stamp order.
class BlockEvents final : public performer::EventSource
{
  public:
    std::vector<std::pair<int, GestureEvent>> events;
    bool next(int sample, GestureEvent& event) noexcept override
    {
        if (next_ == events.size() || events[next_].first > sample)
            return false;
        event = events[next_++].second;
        return true;
    }
    bool remaining(int, GestureEvent& event) noexcept override
    {
        if (next_ == events.size())
            return false;
        event = events[next_++].second;
        return true;
    }

  private:
    std::size_t next_ = 0;
};

class Recording final : public performer::SampleSink
{
  public:
    void take(int, const physics::BowedInstrument& instrument, double bridgeForce) noexcept override
    {
        force.push_back(bridgeForce);
        pressure.push_back(instrument.radiatedPressure());
    }
    std::vector<double> force, pressure;
};

std::vector<double> openFrequencies(const physics::BowedInstrument& instrument)
{
    std::vector<double> f;
    for (int s = 0; s < instrument.stringCount(); ++s)
        f.push_back(instrument.openFrequency(s));
    return f;
}

double totalBowForce(const Performer& p)
{
    double f = 0.0;
    for (int s = 0; s < p.stringCount(); ++s)
        f += p.input(s).bowForce;
    return f;
}

struct Stamped
{
    long sample; ///< absolute
    GestureEvent event;
};

// A cello played for `total` samples in blocks of the lengths `blocks` (repeated); each event is handed over
// with the block that contains its sample, and the `late` ones with the first block, stamped past its end.
Recording play(const std::vector<int>& blocks, const std::vector<Stamped>& events, long total,
               const std::vector<GestureEvent>& late = {})
{
    physics::BowedInstrument cello;
    cello.prepare(physics::celloInstrument(), kRate);
    const auto f = openFrequencies(cello);
    Performer p;
    p.prepare(1, f.data(), static_cast<int>(f.size()), kRate);
    Recording out;
    for (long start = 0, b = 0; start < total; ++b)
    {
        const int n = static_cast<int>(
            std::min<long>(blocks[static_cast<std::size_t>(b) % blocks.size()], total - start));
        BlockEvents source;
        for (const auto& e : events)
            if (e.sample >= start && e.sample < start + n)
                source.events.emplace_back(static_cast<int>(e.sample - start), e.event);
        if (start == 0)
            for (const auto& e : late)
                source.events.emplace_back(n + 1000, e);
        p.follow(1, f.data(), static_cast<int>(f.size()), kRate);
        p.beginBlock({});
        p.process(cello, source, out, n);
        start += n;
    }
    return out;
}

double peakAbs(const std::vector<double>& x, std::size_t from, std::size_t to)
{
    double peak = 0.0;
    for (std::size_t i = from; i < to; ++i)
        peak = std::max(peak, std::abs(x[i]));
    return peak;
}

TEST(Performer, HowTheBlocksAreCutDoesNotChangeASample)
{
    const long total = static_cast<long>(0.4 * kRate);
    const std::vector<Stamped> note{{100, GestureEvent::noteOn(50, 90)},
                                    {static_cast<long>(0.3 * kRate), GestureEvent::noteOff(50)}};
    const Recording whole = play({static_cast<int>(total)}, note, total);
    const Recording cut = play({1, 64, 97, 512, 13}, note, total);
    EXPECT_EQ(whole.force, cut.force);
    EXPECT_EQ(whole.pressure, cut.pressure);
    // Something was played: silence before the note-on, sound after it.
    EXPECT_EQ(peakAbs(whole.pressure, 0, 100), 0.0);
    EXPECT_GT(peakAbs(whole.pressure, 100, whole.pressure.size()), 1e-3);
}

TEST(Performer, AnEventStampedPastItsBlockActsBeforeTheNextBlock)
{
    // A note-on stamped beyond the first 256-sample block plays from the second block on, exactly as the same
    // note-on stamped at that block's first sample.
    const long total = 4096;
    const Recording late = play({256}, {}, total, {GestureEvent::noteOn(50, 90)});
    const Recording onTime = play({256}, {{256, GestureEvent::noteOn(50, 90)}}, total);
    EXPECT_EQ(late.force, onTime.force);
    EXPECT_EQ(peakAbs(late.pressure, 0, 256), 0.0);
    EXPECT_GT(peakAbs(late.pressure, 256, late.pressure.size()), 0.0);
}

TEST(Performer, ARebuiltInstrumentWithTheSameStringsKeepsTheGesture)
{
    physics::BowedInstrument cello;
    cello.prepare(physics::celloInstrument(), kRate);
    const auto f = openFrequencies(cello);
    Performer p;
    p.prepare(1, f.data(), static_cast<int>(f.size()), kRate);
    BlockEvents first;
    first.events = {{0, GestureEvent::noteOn(50, 90)}};
    Recording out;
    p.beginBlock({});
    p.process(cello, first, out, 2400);
    ASSERT_GT(totalBowForce(p), 0.0);

    // Serial 2, the same strings (a rebuilt cello): the bow stays on the string.
    BlockEvents none;
    p.follow(2, f.data(), static_cast<int>(f.size()), kRate);
    p.beginBlock({});
    p.process(cello, none, out, 240);
    EXPECT_GT(totalBowForce(p), 0.0);

    // Serial 3, other strings (a violin): the gesture starts again from rest.
    physics::BowedInstrument violin;
    violin.prepare(physics::violinInstrument(), kRate);
    const auto g = openFrequencies(violin);
    p.follow(3, g.data(), static_cast<int>(g.size()), kRate);
    p.beginBlock({});
    p.process(violin, none, out, 240);
    EXPECT_EQ(totalBowForce(p), 0.0);
}

} // namespace ROSIN_FILE_LOCAL
