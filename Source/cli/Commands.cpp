#include "cli/Commands.h"

#include "cli/DiscoverCommand.h"
#include "cli/RenderCommand.h"
#include "cli/ScanCommand.h"
#include "cli/SynthDataCommand.h"

namespace rosin::cli
{

const std::vector<Command>& commands()
{
    // One entry (and one file) per subcommand.
    static const std::vector<Command> list = {
        {"render", "render a bow gesture or a MIDI file to a WAV of what a listener hears (and a probe)",
         runRender, renderHelpPage, checkRenderArguments},
        {"scan", "Schelleng and Guettler playability diagrams over a grid of bowings (all cores, resumable)",
         runScan, scanHelpPage, checkScanArguments},
        {"synth-data",
         "a measured-like dataset from the model with physical effects hidden (discovery test data)",
         runSynthData, synthDataHelpPage, checkSynthDataArguments},
        {"discover", "where a measured dataset and the model disagree, and which physical effect is missing",
         runDiscover, discoverHelpPage, checkDiscoverArguments},
    };
    return list;
}

const Command* findCommand(const std::string& name)
{
    for (const Command& c : commands())
        if (name == c.name)
            return &c;
    return nullptr;
}

} // namespace rosin::cli
