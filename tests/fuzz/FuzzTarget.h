#pragma once
// What every fuzz target shares: the libFuzzer entry point, and the one rule they check besides the
// sanitizers: bad input must end in the reader's own error (naming file, field and expectation), never in
// another exception, a crash, a hang or a non-finite value. Anything else aborts, which is a finding.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace rosin::fuzz
{

inline std::string asText(const std::uint8_t* data, std::size_t size)
{
    return std::string(reinterpret_cast<const char*>(data), size);
}

/// Aborts (a finding) when `value` is not finite: accepted input must never produce NaN or infinity.
inline void requireFinite(double value, const char* what)
{
    if (!std::isfinite(value))
    {
        std::fprintf(stderr, "fuzz finding: %s is not finite (%g)\n", what, value);
        std::abort();
    }
}

} // namespace rosin::fuzz
