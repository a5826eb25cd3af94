// Measured datasets' trial files (WAV, IEEE float 32-bit, one channel per dataset channel): bytes -> a file
// in a scratch folder -> readTrialSignals against a two-channel 44.1 kHz description. A file the reader
// accepts must hold finite samples of the declared shape.
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "fuzz/FuzzTarget.h"
#include "lab/discovery/io/TrialSignals.h"

namespace
{

rosin::discovery::Dataset twoChannelDataset(const std::filesystem::path& folder)
{
    rosin::discovery::Dataset d;
    d.folder = folder.string();
    d.sampleRate = 44100;
    d.channels = {{"bridgeForce", "N"}, {"bowVelocity", "m/s"}};
    return d;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace rosin;
    static const std::filesystem::path folder =
        std::filesystem::temp_directory_path() / ("rosin-fuzz-wav-" + std::to_string(::getpid()));
    static const discovery::Dataset dataset = twoChannelDataset(folder);
    std::filesystem::create_directories(folder / "trials");
    {
        std::ofstream out(folder / "trials" / "t.wav", std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    }
    discovery::Trial trial;
    trial.id = "t";
    trial.file = "trials/t.wav";
    try
    {
        const discovery::TrialSignals signals = discovery::readTrialSignals(dataset, trial);
        if (signals.channels.size() != 2 || signals.samples.size() != 2 || signals.frames() == 0)
            std::abort();
        for (const auto& channel : signals.samples)
            for (double v : channel)
                fuzz::requireFinite(v, "trial sample");
    }
    catch (const discovery::DatasetError&)
    {
    }
    return 0;
}
