#include "instrument/plugin/ProgramFile.h"

#include "core/config/ConfigError.h"
#include "core/config/JsonFile.h"
#include "core/config/PresetLoader.h"

namespace rosin::plugin
{

namespace
{
const juce::Identifier kProgramPathProperty{"programFile"};
const juce::Identifier kProgramTextProperty{"programFileText"};
} // namespace

std::variant<ProgramFile, std::string> parseProgramText(const std::string& text, const juce::String& path)
{
    const std::string file = path.toStdString();
    try
    {
        const nlohmann::json root = config::parseJsonText(text, file);
        const std::string stem =
            juce::File::createFileWithoutCheckingPath(path).getFileNameWithoutExtension().toStdString();
        return ProgramFile{path, text, config::parsePreset(root, file, stem)};
    }
    catch (const config::ConfigError& e)
    {
        return std::string(e.what());
    }
}

std::variant<ProgramFile, std::string> readProgramFile(const juce::File& file)
{
    const std::string path = file.getFullPathName().toStdString();
    if (!file.existsAsFile())
        return path + ": no such file (expected a program file, a preset in JSON)";
    if (file.getSize() > kMaxProgramFileBytes)
        return path + ": " + std::to_string(file.getSize()) + " bytes, expected a program file of at most " +
               std::to_string(kMaxProgramFileBytes);
    juce::MemoryBlock bytes;
    if (!file.loadFileAsData(bytes))
        return path + ": cannot be read";
    return parseProgramText(bytes.toString().toStdString(), file.getFullPathName());
}

void saveProgramFile(const ProgramFile& program, juce::ValueTree& state)
{
    state.setProperty(kProgramPathProperty, program.path, nullptr);
    state.setProperty(kProgramTextProperty, juce::String(program.text), nullptr);
}

std::optional<ProgramFile> restoreProgramFile(juce::ValueTree& state, std::string& problem)
{
    problem.clear();
    if (!state.hasProperty(kProgramTextProperty))
        return std::nullopt;
    const juce::String path = state.getProperty(kProgramPathProperty).toString();
    const std::string text = state.getProperty(kProgramTextProperty).toString().toStdString();
    state.removeProperty(kProgramPathProperty, nullptr);
    state.removeProperty(kProgramTextProperty, nullptr);
    auto parsed = parseProgramText(text, path.isEmpty() ? juce::String("saved program") : path);
    if (auto* error = std::get_if<std::string>(&parsed))
    {
        problem = "the saved program file's copy: " + *error;
        return std::nullopt;
    }
    return std::get<ProgramFile>(std::move(parsed));
}

} // namespace rosin::plugin
