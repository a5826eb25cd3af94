#include "FactoryPrograms.h"

#include <exception>
#include <iostream>

#include "config/PresetLoader.h"

namespace rosin::plugin
{

std::vector<FactoryProgram> loadFactoryPrograms()
{
    std::vector<FactoryProgram> programs;
    try
    {
        for (const auto& name : config::presetNames())
        {
            try
            {
                config::Preset preset = config::loadPreset(name);
                if (preset.rig) // seed 000's oscillator rig: played by `rosin render`, not by the instrument
                    continue;
                programs.push_back({name, std::move(preset)});
            }
            catch (const std::exception& e)
            {
                std::cerr << "rosin: skipping preset " << name << ": " << e.what() << "\n";
            }
        }
    }
    catch (const std::exception& e)
    {
        std::cerr << "rosin: no factory presets: " << e.what() << "\n";
    }
    if (programs.empty())
        programs.push_back({config::defaultPreset().name, config::defaultPreset()});
    return programs;
}

int findProgram(const std::vector<FactoryProgram>& programs, const std::string& name)
{
    for (std::size_t i = 0; i < programs.size(); ++i)
        if (programs[i].name == name)
            return static_cast<int>(i);
    return 0;
}

} // namespace rosin::plugin
