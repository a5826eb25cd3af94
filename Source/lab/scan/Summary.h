#pragma once
// DIR/scan.json (Resources/docs/scan-format.md): the scan's settings, the share of Helmholtz cells, the
// theory it is compared with (Theory.h) and, for Schelleng, the fitted edges of the Helmholtz region
// (BoundaryFit.h). Guettler scans add "perBeta": cells, Helmholtz cells and reached transients per beta.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lab/scan/CellResult.h"
#include "lab/scan/ScanSpec.h"

namespace rosin::scan
{

/// `results` holds every cell, indexed by cell.
nlohmann::json scanSummary(const ScanSpec& spec, const std::vector<CellResult>& results);
/// The figures plot_scan.py draws for a scan of this kind (the contract's names).
std::vector<std::string> figureNames(ScanKind kind);

} // namespace rosin::scan
