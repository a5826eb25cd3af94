#pragma once
// Checks that a malformed preset file is refused by name: the file, the field and what was expected.
#include <gtest/gtest.h>

#include <string>

#include "core/config/ConfigError.h"
#include "core/config/PresetLoader.h"

namespace rosin::test
{

/// Loads `path` and expects a ConfigError naming that file, `field`, and an expectation containing
/// `expected`; `what` labels the failures.
inline void expectPresetRefused(const std::string& path, const std::string& field,
                                const std::string& expected, const std::string& what)
{
    try
    {
        config::loadPreset(path);
        ADD_FAILURE() << what << " was accepted";
    }
    catch (const config::ConfigError& e)
    {
        EXPECT_EQ(e.file(), path);
        EXPECT_EQ(e.field(), field) << what;
        EXPECT_NE(e.expected().find(expected), std::string::npos) << what << ": " << e.expected();
    }
}

} // namespace rosin::test
