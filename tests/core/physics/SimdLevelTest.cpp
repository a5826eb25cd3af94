// The kernels' vector level (physics/modal/SimdLevel.h): what ROSIN_SIMD may force, never above the CPU.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>

#include "core/physics/modal/SimdLevel.h"

using namespace rosin::physics;

TEST(SimdLevel, NamesAreTheOnesRosinSimdAccepts)
{
    EXPECT_STREQ(simdLevelName(SimdLevel::Default), "default");
    EXPECT_STREQ(simdLevelName(SimdLevel::V3), "x86-64-v3");
    EXPECT_STREQ(simdLevelName(SimdLevel::V4), "x86-64-v4");
}

TEST(SimdLevel, InUseIsWhatWasAskedForWithinWhatTheCpuHas)
{
    EXPECT_LE(simdLevel(), supportedSimdLevel());
    const char* wanted = std::getenv("ROSIN_SIMD");
    if (wanted == nullptr || *wanted == '\0')
        EXPECT_EQ(simdLevel(), supportedSimdLevel());
    else if (std::strcmp(wanted, simdLevelName(simdLevel())) != 0)
        EXPECT_EQ(simdLevel(), supportedSimdLevel()); // asked above the CPU: the best it has
    std::printf("[figure] kernels at %s (CPU supports %s)\n", simdLevelName(simdLevel()),
                simdLevelName(supportedSimdLevel()));
}
