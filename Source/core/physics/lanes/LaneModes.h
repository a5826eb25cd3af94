#pragma once
// One modal bank (ModalBank.h) advanced for kLanes independent trials at once: the poles, input gains and
// output weights are shared, each lane has its own state. The state is stored mode by mode with the lanes
// side by side, so one vector instruction advances one mode of every lane; no sums cross the lanes, so a
// lane's result never depends on what the others compute (a scan cell comes out the same whichever cells
// share its batch). Used by VoiceLanes for scans; the per-sample step of one voice stays in ModalKernels.
#include <vector>

#include "core/physics/modal/ModalKernels.h"

namespace rosin::physics
{

/// Trials advanced together: eight floats fill one AVX2 register.
inline constexpr int kLanes = 8;

/// One value per lane.
struct LaneValues
{
    alignas(32) ModalReal v[kLanes] = {};
};

/// The state of one mode in every lane, as one vector (GCC/Clang vector extension: an AVX2 register on
/// x86-64-v3, two SSE registers otherwise).
typedef ModalReal LaneVector __attribute__((vector_size(kLanes * sizeof(ModalReal))));

/// The complex state w~ of one mode in every lane. A struct, so that std::vector keeps its alignment (a
/// vector typedef's own alignment is dropped as a template argument, and the AVX2 clones load it aligned).
struct alignas(32) ModeState
{
    LaneVector re, im;
};

struct LaneModes
{
    int modes = 0;
    std::vector<ModalReal> pRe, pIm;     ///< shared digital poles
    std::vector<ModalReal> gainA, gainB; ///< shared input gains, times the time step T
    OutputWeights out1, out2, out3;      ///< shared output weights (unused ones stay empty)
    std::vector<ModeState> w;            ///< state, one per mode

    /// Copies a bank's poles, its input gains (gainB may be null) and up to three output weights.
    void assign(const ModalBank& bank, const ModalReal* gainA, const ModalReal* gainB,
                const OutputWeights* o1, const OutputWeights* o2 = nullptr,
                const OutputWeights* o3 = nullptr);
    void reset() noexcept;
    void resetLane(int lane) noexcept;
};

/// x = gainA a + gainB b per lane; advance; the two output sums over the new state.
void advanceTwoInputsTwoOutputs(LaneModes& bank, const LaneValues& a, const LaneValues& b, LaneValues& s1,
                                LaneValues& s2) noexcept;
/// x = gainA a; advance; the one output sum.
void advanceOneInputOneOutput(LaneModes& bank, const LaneValues& a, LaneValues& s1) noexcept;
/// x = gainA a; advance; the three output sums.
void advanceOneInputThreeOutputs(LaneModes& bank, const LaneValues& a, LaneValues& s1, LaneValues& s2,
                                 LaneValues& s3) noexcept;

} // namespace rosin::physics
