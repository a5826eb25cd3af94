#pragma once
// scan.csv rows (Resources/docs/scan-format.md): the header of each kind, one CellResult as one line and
// back. Numbers are printed with "%.9g", so a row is the same bytes whichever process computed it; an empty
// field is an absent value.
#include <string>

#include "lab/scan/CellResult.h"
#include "lab/scan/ScanSpec.h"

namespace rosin::scan
{

/// The header line (no newline): "cell,beta,bowForce,acceleration,..." or "...,bowSpeed,...".
std::string csvHeader(ScanKind kind);
/// One row (no newline).
std::string formatRow(const CellResult& result);
/// Parses a row written by formatRow. Throws std::invalid_argument saying what is wrong.
CellResult parseRow(const std::string& line);
/// The cell index of a row (its first field). Throws std::invalid_argument.
std::size_t rowCell(const std::string& line);

} // namespace rosin::scan
