// The kernels' vector level (SimdLevel.h).
#include "core/physics/modal/SimdLevel.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <initializer_list>

namespace rosin::physics
{

const char* simdLevelName(SimdLevel level) noexcept
{
    switch (level)
    {
    case SimdLevel::V4:
        return "x86-64-v4";
    case SimdLevel::V3:
        return "x86-64-v3";
    case SimdLevel::Default:
        break;
    }
    return "default";
}

SimdLevel supportedSimdLevel() noexcept
{
// Clang (the fuzzing build) knows neither arch=x86-64-v4 targets nor those names in __builtin_cpu_supports
// before version 16: it gets the baseline kernels only.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(ROSIN_NO_MULTIVERSION)
    __builtin_cpu_init();
    if (__builtin_cpu_supports("x86-64-v4"))
        return SimdLevel::V4;
    if (__builtin_cpu_supports("x86-64-v3"))
        return SimdLevel::V3;
#endif
    return SimdLevel::Default;
}

namespace
{
SimdLevel chooseLevel() noexcept
{
    const SimdLevel best = supportedSimdLevel();
    const char* wanted = std::getenv("ROSIN_SIMD");
    if (wanted == nullptr || *wanted == '\0')
        return best;
    for (SimdLevel level : {SimdLevel::Default, SimdLevel::V3, SimdLevel::V4})
        if (std::strcmp(wanted, simdLevelName(level)) == 0)
        {
            if (level <= best)
                return level;
            std::fprintf(stderr, "rosin: ROSIN_SIMD=%s is not supported by this CPU; using %s\n", wanted,
                         simdLevelName(best));
            return best;
        }
    std::fprintf(stderr, "rosin: ROSIN_SIMD: expected default, x86-64-v3 or x86-64-v4 but got \"%s\"\n",
                 wanted);
    std::exit(2);
}
} // namespace

SimdLevel simdLevel() noexcept
{
    static const SimdLevel level = chooseLevel();
    return level;
}

} // namespace rosin::physics
