#pragma once
// Which vector-instruction level the hot kernels (ModalKernels, LaneModes) run at. By default the best this
// CPU supports; ROSIN_SIMD=default|x86-64-v3|x86-64-v4 forces a lower one, so that one machine can run the
// suite on every path a user's machine might take (the baseline path, without fused multiply-adds, rounds
// differently from the other two, and chaotic transients amplify that). Read once, before the first kernel
// call.
namespace rosin::physics
{

enum class SimdLevel
{
    Default, ///< SSE2 (x86-64 baseline), or no multiversioning at all off x86-64
    V3,      ///< x86-64-v3: AVX2, FMA
    V4       ///< x86-64-v4: AVX-512
};

/// "default", "x86-64-v3", "x86-64-v4".
const char* simdLevelName(SimdLevel level) noexcept;
/// The best level this CPU supports.
SimdLevel supportedSimdLevel() noexcept;
/// The level in use: ROSIN_SIMD if set (lowered to what the CPU supports, with a warning on stderr; an
/// unknown name is an error that names the variable and the accepted values, and exits), else the best.
SimdLevel simdLevel() noexcept;

} // namespace rosin::physics
