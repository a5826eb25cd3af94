// Standard MIDI files (rosin render --midi): bytes -> JUCE's reader with Rosin's merge and tempo map -> every
// channel message through the bow controller of a four-string cello, which must keep its inputs finite.
#include <juce_audio_basics/juce_audio_basics.h>

#include "fuzz/FuzzTarget.h"
#include "instrument/engine/MidiInput.h"
#include "instrument/player/MidiBytes.h"
#include "instrument/player/MidiGestureController.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace rosin;
    juce::MidiMessageSequence sequence;
    try
    {
        juce::MemoryInputStream in(data, size, false);
        sequence = engine::readMidiStream(in, "fuzz.mid");
    }
    catch (const std::runtime_error&)
    {
        return 0;
    }
    static const double openStrings[] = {65.41, 98.0, 146.83, 220.0};
    player::MidiGestureController controller;
    controller.prepare(openStrings, 4, 8000.0);
    physics::BowInput inputs[player::MidiGestureController::kMaxStrings];
    const int events = std::min(sequence.getNumEvents(), 4096);
    for (int e = 0; e < events; ++e)
    {
        const juce::MidiMessage& message = sequence.getEventPointer(e)->message;
        fuzz::requireFinite(message.getTimeStamp(), "event time");
        player::GestureEvent event;
        if (player::decodeMidi(message.getRawData(), message.getRawDataSize(), 0, event))
            controller.handleEvent(event);
        controller.next(inputs);
        for (int s = 0; s < controller.stringCount(); ++s)
        {
            fuzz::requireFinite(inputs[s].bowForce, "bow force");
            fuzz::requireFinite(inputs[s].bowVelocity, "bow velocity");
            fuzz::requireFinite(inputs[s].beta, "beta");
        }
    }
    return 0;
}
