#include "instrument/player/StringChoice.h"

#include <algorithm>
#include <cmath>

namespace rosin::player
{

double noteFrequency(double midiNote) noexcept
{
    return 440.0 * std::exp2((midiNote - 69.0) / 12.0);
}

double pitchOfFrequency(double frequencyHz) noexcept
{
    return 69.0 + 12.0 * std::log2(frequencyHz / 440.0);
}

int defaultString(const double* openFrequenciesHz, int count, double note) noexcept
{
    int chosen = 0;
    for (int i = 0; i < count; ++i)
        if (pitchOfFrequency(openFrequenciesHz[i]) <= note + 0.5)
            chosen = i;
    return chosen;
}

double fingerRatio(double openFrequencyHz, double note) noexcept
{
    return std::clamp(openFrequencyHz / noteFrequency(note), 0.1, 1.0);
}

} // namespace rosin::player
