// The regime names are a file format: CSV files written today must parse tomorrow.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "core/analysis/Regime.h"

using namespace rosin::analysis;

TEST(Regime, NamesAreTheDocumentedOnesAndRoundTrip)
{
    const char* expected[] = {"helmholtz", "s-motion", "double-slipping",   "multiple-slipping",
                              "raucous",   "alf",      "constant-slipping", "no-slip"};
    const auto regimes = allRegimes();
    ASSERT_EQ(regimes.size(), std::size(expected));
    std::set<std::string> seen;
    for (std::size_t i = 0; i < regimes.size(); ++i)
    {
        EXPECT_STREQ(regimeName(regimes[i]), expected[i]);
        EXPECT_EQ(parseRegime(expected[i]), regimes[i]);
        seen.insert(regimeName(regimes[i]));
    }
    EXPECT_EQ(seen.size(), regimes.size());
}

TEST(Regime, ParseRejectsUnknownNamesAndAcceptsSilent)
{
    EXPECT_FALSE(parseRegime("Helmholtz").has_value()); // exact, lower case
    EXPECT_FALSE(parseRegime("").has_value());
    EXPECT_FALSE(parseRegime("helmholtz ").has_value());
    EXPECT_EQ(parseRegime("silent"), Regime::NoSlip);
}
