#pragma once
// The independent generator's random streams: its own numbers beside SeededRandom's RandomStream values, so
// that its draws never coincide with rosin synth-data's (which it reuses for the plan: jitter, faults).
#include "lab/discovery/SeededRandom.h"

namespace rosin::discovery::independent_streams
{

inline constexpr RandomStream kNuisance = static_cast<RandomStream>(101);   ///< one per dataset
inline constexpr RandomStream kOwnEffect = static_cast<RandomStream>(102);  ///< index: catalog place
inline constexpr RandomStream kChain = static_cast<RandomStream>(103);      ///< one per dataset
inline constexpr RandomStream kStartDelay = static_cast<RandomStream>(104); ///< index: the trial
inline constexpr RandomStream kNoise = static_cast<RandomStream>(105);      ///< index: the trial
inline constexpr RandomStream kMember = static_cast<RandomStream>(106);     ///< seeded by the member number

} // namespace rosin::discovery::independent_streams
