// The peer of a whole-process render (benchmarks/render_vs_stk.py): STK's Bowed instrument bowing D3
// (146.83 Hz) for SECONDS at 48 kHz, written by STK's own FileWvOut as a mono 32-bit float WAV, as one
// process from start to exit, so that it can be timed against `rosin render` doing the same job.
//
//     stk-render SECONDS OUT.wav
#include <stk/Bowed.h>
#include <stk/FileWvOut.h>

#include <cstdio>
#include <cstdlib>
#include <exception>

int main(int argc, char** argv)
{
    if (argc != 3)
    {
        std::fprintf(stderr, "usage: stk-render SECONDS OUT.wav\n");
        return 2;
    }
    const double seconds = std::atof(argv[1]);
    if (!(seconds > 0.0 && seconds <= 3600.0))
    {
        std::fprintf(stderr, "stk-render: SECONDS: expected 0 < s <= 3600, got \"%s\"\n", argv[1]);
        return 2;
    }
    try
    {
        stk::Stk::setSampleRate(48000.0);
        stk::Bowed bowed(65.0); // lowest frequency 65 Hz: a cello's C string
        stk::FileWvOut out(argv[2], 1, stk::FileWrite::FILE_WAV, stk::Stk::STK_FLOAT32);
        bowed.noteOn(146.83, 0.8);
        const long samples = static_cast<long>(seconds * 48000.0);
        for (long k = 0; k < samples; ++k)
            out.tick(bowed.tick());
    }
    catch (const std::exception& e)
    {
        std::fprintf(stderr, "stk-render: %s\n", e.what());
        return 1;
    }
    return 0;
}
