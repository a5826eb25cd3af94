#include "instrument/performer/Performer.h"

#include <algorithm>

namespace rosin::performer
{

void Performer::prepare(long serial, const double* openFrequencies, int strings, double sampleRate)
{
    prepareGesture(openFrequencies, strings, sampleRate);
    serial_ = serial;
    for (auto& m : meters_)
        m.prepare(sampleRate);
}

void Performer::prepareGesture(const double* openFrequencies, int strings, double sampleRate) noexcept
{
    strings_ = std::clamp(strings, 0, kMaxStrings);
    std::copy(openFrequencies, openFrequencies + strings_, openFrequencies_.begin());
    controller_.prepare(openFrequencies, strings_, sampleRate);
    for (int s = 0; s < strings_; ++s)
        ears_[static_cast<std::size_t>(s)].prepare(openFrequencies[s], sampleRate);
}

void Performer::follow(long serial, const double* openFrequencies, int strings, double sampleRate) noexcept
{
    if (serial == serial_)
        return;
    // A rebuilt instrument starts at rest; the gesture continues unless the strings changed.
    bool sameStrings = serial_ >= 0 && controller_.stringCount() == strings;
    for (int i = 0; sameStrings && i < strings; ++i)
        sameStrings = controller_.openFrequency(i) == openFrequencies[i];
    if (!sameStrings)
        prepareGesture(openFrequencies, strings, sampleRate);
    serial_ = serial;
}

void Performer::reset() noexcept
{
    controller_.reset();
    for (auto& m : meters_)
        m.reset();
    for (auto& ear : ears_)
        ear.reset();
}

void Performer::beginBlock(const BlockSettings& settings) noexcept
{
    controller_.setParameters(settings.gesture);
    for (int s = 0; s < strings_; ++s)
        ears_[static_cast<std::size_t>(s)].setEnabled(settings.intonationByEar);
    for (int s = 0; s < strings_; ++s)
    {
        // The finger ratio of the previous sample: good enough for the regime's nominal period.
        const auto k = static_cast<std::size_t>(s);
        const double ratio = inputs_[k].fingerRatio > 0.0 ? inputs_[k].fingerRatio : 1.0;
        meters_[k].setNominalFrequency(openFrequencies_[k] / ratio);
    }
}

int Performer::process(physics::BowedInstrument& instrument, EventSource& events, SampleSink& sink,
                       int n) noexcept
{
    int runaways = 0;
    player::GestureEvent event;
    for (int i = 0; i < n; ++i)
    {
        while (events.next(i, event))
            controller_.handleEvent(event);
        controller_.next(inputs_.data());
        for (int s = 0; s < strings_; ++s)
        {
            auto& in = inputs_[static_cast<std::size_t>(s)];
            in.fingerRatio = ears_[static_cast<std::size_t>(s)].finger(in.fingerRatio);
        }
        const double bridgeForce = instrument.step(inputs_.data(), outputs_.data());
        if (instrument.recoveredFromRunaway())
            ++runaways;
        for (int s = 0; s < strings_; ++s)
        {
            const auto k = static_cast<std::size_t>(s);
            meters_[k].push(outputs_[k], inputs_[k].bowForce);
            ears_[k].listen(outputs_[k].sticking, outputs_[k].bowPointVelocity, outputs_[k].bowVelocity);
        }
        sink.take(i, instrument, bridgeForce);
    }
    while (events.remaining(n, event)) // stamped past the block's end (malformed host data)
        controller_.handleEvent(event);
    return runaways;
}

} // namespace rosin::performer
