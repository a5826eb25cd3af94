#include "instrument/engine/FactoryPrograms.h"

#include <algorithm>
#include <exception>
#include <filesystem>
#include <iostream>
#include <optional>

#include "FactoryPresetData.h"
#include "core/config/JsonFile.h"
#include "core/config/PresetLoader.h"
#include "instrument/engine/EngineParameters.h"
#include "instrument/engine/InstrumentSetup.h"

namespace rosin::engine
{

namespace
{
/// One embedded presets/*.json, parsed like a preset file (errors name "presets/NAME.json").
std::optional<FactoryProgram> parseEmbedded(const char* resourceName)
{
    const std::string fileName = FactoryPresetData::getNamedResourceOriginalFilename(resourceName);
    if (std::filesystem::path(fileName).extension() != ".json")
        return std::nullopt;
    int bytes = 0;
    const char* data = FactoryPresetData::getNamedResource(resourceName, bytes);
    const std::string file = "presets/" + fileName;
    try
    {
        const std::string stem = std::filesystem::path(fileName).stem().string();
        config::Preset preset = config::parsePreset(
            config::parseJsonText(std::string(data, static_cast<std::size_t>(bytes)), file), file, stem);
        if (preset.rig) // [Smith2000]'s oscillator rig: played by `rosin render`, not by the instrument
            return std::nullopt;
        return FactoryProgram{stem, std::move(preset)};
    }
    catch (const std::exception& e)
    {
        std::cerr << "rosin: skipping preset " << file << ": " << e.what() << "\n";
        return std::nullopt;
    }
}
} // namespace

std::vector<FactoryProgram> loadFactoryPrograms()
{
    std::vector<FactoryProgram> programs;
    for (int i = 0; i < FactoryPresetData::namedResourceListSize; ++i)
        if (auto program = parseEmbedded(FactoryPresetData::namedResourceList[i]))
            programs.push_back(std::move(*program));
    std::sort(programs.begin(), programs.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
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

std::vector<std::pair<const char*, float>> programParameterValues(const config::Preset& preset)
{
    auto values = instrumentParameterValues(preset);
    config::PlayerPreset lab;
    lab.mapping = "lab";
    const config::PlayerPreset player = preset.player.value_or(lab);
    const player::GestureParameters defaults{};
    values.emplace_back(ids::mapping, player.mapping == "musical" ? 1.0f : 0.0f);
    const auto add = [&](const char* id, std::optional<double> value, double fallback)
    { values.emplace_back(id, static_cast<float>(value.value_or(fallback))); };
    add(ids::dynamics, player.dynamics, defaults.dynamics);
    add(ids::bowPressure, player.bowPressure, defaults.bowPressure);
    add(ids::vibratoDepth, player.vibratoDepth, defaults.vibratoDepth);
    add(ids::vibratoRate, player.vibratoRate, defaults.vibratoRate);
    add(ids::vibratoDelay, player.vibratoDelay, defaults.vibratoDelay);
    add(ids::slideTime, player.slideTime, defaults.slideTime);
    add(ids::tremoloRate, player.tremoloRate, defaults.tremoloRate);
    values.emplace_back(ids::articulation, player.articulation.value_or("arco") == "pizzicato" ? 1.0f : 0.0f);
    return values;
}

std::vector<std::pair<const char*, float>> instrumentParameterValues(const config::Preset& preset)
{
    return {{ids::instrument, static_cast<float>(instrumentIndexForPreset(preset))},
            {ids::friction,
             static_cast<float>(static_cast<int>(physics::frictionModelFromName(preset.friction)))},
            {ids::body, preset.body == "rigid" ? 0.0f : 1.0f},
            {ids::ambientTemperature, static_cast<float>(kCalibrationAmbientCelsius + preset.ambientOffset)},
            {ids::beta, static_cast<float>(preset.beta)},
            {ids::outputLevel, static_cast<float>(preset.outputLevel.value_or(kDefaultOutputLevelDb))}};
}

} // namespace rosin::engine
