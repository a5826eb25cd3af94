#pragma once
// A program read from a file instead of the factory list: a preset ("rosin-preset/1",
// Resources/docs/presets.md) such as Resources/scripts/fit_body.py writes for a player's own instrument. Its
// text is kept and saved with the plugin's state, so a project reopens with the same program where the file
// has since moved or changed.
#include <juce_data_structures/juce_data_structures.h>

#include <optional>
#include <string>
#include <variant>

#include "core/config/Preset.h"
#include "instrument/plugin/SavedState.h"

namespace rosin::plugin
{

/// Largest program file accepted, bytes: its text goes into the saved state in an XML attribute, where a
/// quote takes six bytes, and a state is refused beyond kMaxStateBytes (SavedState.h): an eighth of that
/// leaves room for the worst case and the parameters (a 32 kB limit let compact JSON make a 69 kB state that
/// did not reload). A program with radiation gains is about 3 kB, a factory preset under 1 kB.
inline constexpr juce::int64 kMaxProgramFileBytes = kMaxStateBytes / 8;

struct ProgramFile
{
    juce::String path; ///< where it was read from (for the editor and messages)
    std::string text;  ///< the file's content, as read
    config::Preset preset;
};

/// Reads and validates `file`: the program, or why it cannot be used (naming the file and the field).
std::variant<ProgramFile, std::string> readProgramFile(const juce::File& file);
/// Validates a program's text as read from `path` (a saved state's copy).
std::variant<ProgramFile, std::string> parseProgramText(const std::string& text, const juce::String& path);

/// State properties "programFile" (path) and "programFileText" (content).
void saveProgramFile(const ProgramFile& program, juce::ValueTree& state);
/// The program a saved state carries, if any (and removes the properties from `state`); a copy that no
/// longer validates gives nothing and the reason in `problem`.
std::optional<ProgramFile> restoreProgramFile(juce::ValueTree& state, std::string& problem);

} // namespace rosin::plugin
