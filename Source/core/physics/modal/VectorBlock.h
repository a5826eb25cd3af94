#pragma once
// A block of lanes as one value (GCC's vector extension) for the hot kernels compiled per vector unit
// (KernelDispatch.h): the x86-64-v4 variant holds a 64-byte block in one AVX-512 register, v3 in two AVX2
// ones, the baseline in four SSE ones, from the same source. Blocks are copied in and out with memcpy, and
// the helpers are always inlined into one kernel variant, so no call passes a block and no ABI depends on
// the vector unit (the files that use them silence GCC's ABI note, Source/CMakeLists.txt). sumOfLanes adds
// the lanes as a tree: a serial chain of log2(lanes) adds, in the same order on every path.
#include <cstring>

#include "core/physics/modal/KernelDispatch.h"

namespace rosin::physics
{

/// n rounded up to whole blocks of `block` (the kernels' padding: modes, heat terms, lane passes).
constexpr int paddedToWholeBlocks(int n, int block) noexcept
{
    return (n + block - 1) / block * block;
}

template <typename Scalar, int lanes> struct VectorBlockOf
{
    typedef Scalar type __attribute__((vector_size(lanes * sizeof(Scalar))));
};
/// `lanes` values of Scalar as one vector value.
template <typename Scalar, int lanes> using VectorBlock = typename VectorBlockOf<Scalar, lanes>::type;

template <typename Block, typename Scalar> ROSIN_KERNEL_BODY Block loadBlock(const Scalar* p) noexcept
{
    Block b;
    std::memcpy(&b, p, sizeof b);
    return b;
}

template <typename Block, typename Scalar>
ROSIN_KERNEL_BODY void storeBlock(Scalar* p, const Block& b) noexcept
{
    std::memcpy(p, &b, sizeof b);
}

/// Adding and removing 2^-780 (~1.6e-235) leaves every double above ~4e-219 exactly as it is, rounds smaller
/// ones to multiples of 2^-832 (~3.5e-251) and sends those below half of that to zero: a decaying value
/// leaves the normal range through zero, never through the slow denormals, without a compare (GCC 12 turns a
/// vector compare of 64-byte blocks into scalar code).
template <typename Block> ROSIN_KERNEL_BODY Block flushTinyToZero(const Block& b) noexcept
{
    constexpr double kOffset = 0x1p-780;
    return (b + kOffset) - kOffset;
}

/// The sum of a block's lanes, halving it until one lane is left (the v4 kernels: 512 -> 256 -> 128 bits,
/// then two steps inside one register).
template <typename Scalar, int lanes>
ROSIN_KERNEL_BODY Scalar sumOfLanes(const VectorBlock<Scalar, lanes>& b) noexcept
{
    if constexpr (lanes == 1)
        return b[0];
    else
    {
        VectorBlock<Scalar, lanes / 2> low, high;
        std::memcpy(&low, &b, sizeof low);
        std::memcpy(&high, reinterpret_cast<const char*>(&b) + sizeof low, sizeof high);
        return sumOfLanes<Scalar, lanes / 2>(low + high);
    }
}

/// The sum of every lane of `parts` blocks: the blocks halved into one (part j with j + parts / 2 ...), then
/// its lanes. With the blocks holding consecutive runs of lanes, this is the tree sumOfLanes takes over one
/// block of parts x lanes, so kernels of any width add in one order.
template <typename Scalar, int lanes, int parts>
ROSIN_KERNEL_BODY Scalar sumOfParts(VectorBlock<Scalar, lanes> (&block)[parts]) noexcept
{
#pragma GCC unroll 4
    for (int width = parts / 2; width > 0; width /= 2)
#pragma GCC unroll 4
        for (int j = 0; j < width; ++j)
            block[j] += block[j + width];
    return sumOfLanes<Scalar, lanes>(block[0]);
}

} // namespace rosin::physics
