#pragma once
// Manual function multiversioning for the hot kernels: each kernel body is compiled for x86-64-v4,
// x86-64-v3 and the baseline, and a call takes the level SimdLevel.h chose (the best this CPU supports, or
// the one ROSIN_SIMD forces). One well-predicted branch per call, as GCC's own target_clones dispatch costs.
//
// ROSIN_KERNEL_VARIANTS(ret, name, (params), (args)) defines name##V4, name##V3 and name##Base from the
// always-inlined name##Body; ROSIN_KERNEL_DISPATCH(level, name, (args)) calls the one for `level`.
// ROSIN_KERNEL_VARIANTS_BY_WIDTH does the same for a body templated on its vector width in bytes (64, 32
// and 16: one AVX-512, AVX2 or SSE register), for kernels written in blocks of that width (VectorBlock.h);
// GCC splits a block wider than the target's registers poorly.
#include "core/physics/modal/SimdLevel.h"

// Clang (the fuzzing build) knows neither arch=x86-64-v4 targets nor those names in __builtin_cpu_supports
// before version 16: it gets the baseline kernels only.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(ROSIN_NO_MULTIVERSION)
#define ROSIN_KERNEL_BODY static inline __attribute__((always_inline))
#define ROSIN_KERNEL_VARIANTS(ret, name, params, args)                                                       \
    __attribute__((target("arch=x86-64-v4"))) static ret name##V4 params noexcept                            \
    {                                                                                                        \
        return name##Body args;                                                                              \
    }                                                                                                        \
    __attribute__((target("arch=x86-64-v3"))) static ret name##V3 params noexcept                            \
    {                                                                                                        \
        return name##Body args;                                                                              \
    }                                                                                                        \
    static ret name##Base params noexcept                                                                    \
    {                                                                                                        \
        return name##Body args;                                                                              \
    }
#define ROSIN_KERNEL_VARIANTS_BY_WIDTH(ret, name, params, args)                                              \
    __attribute__((target("arch=x86-64-v4"))) static ret name##V4 params noexcept                            \
    {                                                                                                        \
        return name##Body<64> args;                                                                          \
    }                                                                                                        \
    __attribute__((target("arch=x86-64-v3"))) static ret name##V3 params noexcept                            \
    {                                                                                                        \
        return name##Body<32> args;                                                                          \
    }                                                                                                        \
    static ret name##Base params noexcept                                                                    \
    {                                                                                                        \
        return name##Body<16> args;                                                                          \
    }
#define ROSIN_KERNEL_DISPATCH(level, name, args)                                                             \
    switch (level)                                                                                           \
    {                                                                                                        \
    case ::rosin::physics::SimdLevel::V4:                                                                    \
        return name##V4 args;                                                                                \
    case ::rosin::physics::SimdLevel::V3:                                                                    \
        return name##V3 args;                                                                                \
    case ::rosin::physics::SimdLevel::Default:                                                               \
        break;                                                                                               \
    }                                                                                                        \
    return name##Base args
#else
#define ROSIN_KERNEL_BODY static inline
#define ROSIN_KERNEL_VARIANTS(ret, name, params, args)                                                       \
    static ret name##Base params noexcept                                                                    \
    {                                                                                                        \
        return name##Body args;                                                                              \
    }
#define ROSIN_KERNEL_VARIANTS_BY_WIDTH(ret, name, params, args)                                              \
    static ret name##Base params noexcept                                                                    \
    {                                                                                                        \
        return name##Body<16> args;                                                                          \
    }
#define ROSIN_KERNEL_DISPATCH(level, name, args) return ((void)(level), name##Base args)
#endif
