#pragma once
// One fitted number of the discrepancy workflow's models: a parameter of a catalog effect
// (EffectCatalog.h) or a nuisance parameter of the rig and its chain (NuisanceParameters.h). JUCE-free.
#include <string>
#include <vector>

namespace rosin::discovery
{

struct EffectParameter
{
    std::string name{}; ///< "growth", "onsetTime", ...
    std::string unit{}; ///< "" (dimensionless), "s", "N s/m", "K"
    /// The range a fit searches and an explicit value must lie in (for a choice: 0 .. choices - 1).
    double min = 0.0, max = 0.0;
    /// Where rosin synth-data draws a hidden value from: uniform in [drawMin, drawMax]; with `signed`, that
    /// is the magnitude and the sign is drawn too.
    double drawMin = 0.0, drawMax = 0.0;
    bool signedDraw = false;
    /// Fit on a log scale (a positive quantity spanning decades).
    bool logarithmic = false;
    /// Non-empty: a discrete choice; the value is the index of the choice.
    std::vector<std::string> choices{};
    std::string meaning{}; ///< one line, for help and reports
};

} // namespace rosin::discovery
