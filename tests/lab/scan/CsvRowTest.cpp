// scan.csv rows: the contract's headers, "%.9g" numbers, empty fields for absent values, and the parse that
// resume and merge rely on.
#include <gtest/gtest.h>

#include <limits>

#include "lab/scan/CsvRow.h"

using namespace rosin::scan;
using rosin::analysis::Regime;
using rosin::analysis::TransientFailure;

TEST(CsvRow, HeadersMatchTheContract)
{
    EXPECT_EQ(csvHeader(ScanKind::Guettler),
              "cell,beta,bowForce,acceleration,regime,transientPeriods,muStatic,jump,"
              "firstSlipTime,slipsPerPeriod,pitchCents,failure");
    EXPECT_EQ(csvHeader(ScanKind::Schelleng),
              "cell,beta,bowForce,bowSpeed,regime,transientPeriods,muStatic,jump,"
              "firstSlipTime,slipsPerPeriod,pitchCents,failure");
}

TEST(CsvRow, FormatsAndParsesBack)
{
    CellResult r;
    r.cell = 123;
    r.beta = 0.0899;
    r.bowForce = 1.8000000000000003;
    r.second = 1.0 / 3.0;
    r.regime = Regime::SMotion;
    r.transientPeriods = 4.25;
    r.muStatic = 0.8971549937;
    r.jump = 0.186542323;
    r.firstSlipTime = 0.0711458333;
    r.slipsPerPeriod = 1.0;
    r.pitchCents = -0.129837685;
    r.failure = TransientFailure::ProlongedSticking;
    const std::string row = formatRow(r);
    EXPECT_EQ(row,
              "123,0.0899,1.8,0.333333333,s-motion,4.25,0.897154994,0.186542323,0.0711458333,1,-0.129837685,"
              "prolonged-sticking");
    const CellResult back = parseRow(row);
    EXPECT_EQ(back.cell, 123u);
    EXPECT_EQ(back.regime, Regime::SMotion);
    EXPECT_EQ(back.failure, TransientFailure::ProlongedSticking);
    EXPECT_DOUBLE_EQ(*back.transientPeriods, 4.25);
    EXPECT_EQ(formatRow(back), row); // the round trip is stable
    EXPECT_EQ(rowCell(row), 123u);
}

TEST(CsvRow, AbsentValuesAreEmptyFields)
{
    CellResult r;
    r.cell = 7;
    r.beta = 0.18;
    r.bowForce = 3.2;
    r.second = 0.08;
    r.regime = Regime::NoSlip;
    r.pitchCents = std::numeric_limits<double>::quiet_NaN(); // non-finite: written as absent
    const std::string row = formatRow(r);
    EXPECT_EQ(row, "7,0.18,3.2,0.08,no-slip,,,,,,,");
    const CellResult back = parseRow(row);
    EXPECT_FALSE(back.transientPeriods);
    EXPECT_FALSE(back.muStatic);
    EXPECT_FALSE(back.pitchCents);
    EXPECT_FALSE(back.failure);
}

TEST(CsvRow, MalformedRowsAreRejected)
{
    for (const char* bad : {"", "7,0.18,3.2,0.08,no-slip,,,,,,", "x,0.18,3.2,0.08,no-slip,,,,,,,",
                            "7,0.18,3.2,0.08,helmholz,,,,,,,", "7,0.18,abc,0.08,no-slip,,,,,,,",
                            "7,0.18,3.2,0.08,no-slip,,,,,,,fine"})
        EXPECT_THROW(parseRow(bad), std::invalid_argument) << bad;
}
