// The check a state string passes before JUCE's LV2 wrapper decodes it (Lv2StateCheck.h): every string
// JUCE's own encoder writes passes (a real state, and blocks of every size up to 300 bytes, each decoded by
// JUCE back to the same bytes), and the damaged ones an outside state fuzzer found taking a host down are
// refused with a reason that names what is wrong.
#include <gtest/gtest.h>

#include <random>

#include "instrument/plugin/Lv2StateCheck.h"
#include "instrument/plugin/PluginTestSupport.h"
#include "instrument/plugin/SavedState.h"

namespace rosin::test
{
namespace ROSIN_FILE_LOCAL
{

constexpr std::size_t kMax = static_cast<std::size_t>(plugin::kMaxStateBytes);

std::optional<std::string> check(const std::string& s)
{
    return plugin::damagedStateString(s.c_str(), s.size() + 1, kMax); // as stored: with its NUL
}

TEST(Lv2StateCheck, WhatJucesEncoderWritesPasses)
{
    plugin::RosinProcessor processor;
    juce::MemoryBlock state;
    processor.getStateInformation(state);
    ASSERT_GT(state.getSize(), 100u);
    EXPECT_EQ(check(state.toBase64Encoding().toStdString()), std::nullopt);

    std::mt19937 random(7);
    for (std::size_t n = 0; n <= 300; ++n)
    {
        juce::MemoryBlock block(n);
        for (std::size_t i = 0; i < n; ++i)
            static_cast<std::uint8_t*>(block.getData())[i] = static_cast<std::uint8_t>(random());
        const std::string text = block.toBase64Encoding().toStdString();
        ASSERT_EQ(check(text), std::nullopt) << n << " bytes: " << text;
        juce::MemoryBlock decoded;
        ASSERT_TRUE(decoded.fromBase64Encoding(text));
        EXPECT_EQ(decoded, block) << n;
    }
}

TEST(Lv2StateCheck, DamagedCountsAreRefusedWithTheReason)
{
    plugin::RosinProcessor processor;
    juce::MemoryBlock state;
    processor.getStateInformation(state);
    const std::string good = state.toBase64Encoding().toStdString();
    const std::string payload = good.substr(good.find('.'));
    for (const std::string count :
         {"-1", "-2147483648", "99999999999999999999", "4294967296", "65537", "", "+12", " 12", "1e3"})
    {
        const auto why = check(count + payload);
        ASSERT_TRUE(why.has_value()) << count;
        EXPECT_NE(why->find("count"), std::string::npos) << *why;
    }
    // A count in range that does not match the payload's length.
    const auto size = std::to_string(state.getSize() + 1);
    ASSERT_TRUE(check(size + payload).has_value());
    EXPECT_NE(check(size + payload)->find("expected"), std::string::npos);
    // Characters outside JUCE's alphabet, no count at all, nothing.
    std::string bad = good;
    bad[bad.size() / 2] = '/';
    EXPECT_TRUE(check(bad).has_value());
    EXPECT_TRUE(check("no count here").has_value());
    EXPECT_TRUE(check("").has_value());
    EXPECT_TRUE(plugin::damagedStateString(nullptr, 0, kMax).has_value());
    // A string the host stored without its NUL, or with a stray NUL in the payload.
    EXPECT_EQ(plugin::damagedStateString(good.data(), good.size(), kMax), std::nullopt);
    std::string nul = good;
    nul[nul.size() / 2] = '\0';
    EXPECT_TRUE(plugin::damagedStateString(nul.data(), nul.size(), kMax).has_value());
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::test
