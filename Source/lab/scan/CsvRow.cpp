#include "lab/scan/CsvRow.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

namespace rosin::scan
{

namespace
{
constexpr std::size_t kFields = 12;

std::string number(double value)
{
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%.9g", value);
    return buffer;
}

// Absent and non-finite values are both written as an empty field.
std::string optionalNumber(const std::optional<double>& value)
{
    return value && std::isfinite(*value) ? number(*value) : std::string();
}

std::vector<std::string> splitFields(const std::string& line)
{
    std::vector<std::string> fields(1);
    for (const char c : line)
        if (c == ',')
            fields.emplace_back();
        else
            fields.back() += c;
    return fields;
}

double parseDouble(const std::string& text, const char* field)
{
    double value = 0.0;
    const char* last = text.data() + text.size();
    const auto r = std::from_chars(text.data(), last, value);
    if (text.empty() || r.ec != std::errc() || r.ptr != last)
        throw std::invalid_argument(std::string("field ") + field + ": expected a number but got \"" + text +
                                    "\"");
    return value;
}

std::optional<double> parseOptional(const std::string& text, const char* field)
{
    if (text.empty())
        return std::nullopt;
    return parseDouble(text, field);
}

std::optional<analysis::TransientFailure> parseFailure(const std::string& text)
{
    if (text.empty())
        return std::nullopt;
    for (const auto f : {analysis::TransientFailure::None, analysis::TransientFailure::MultipleSlipping,
                         analysis::TransientFailure::ProlongedSticking})
        if (text == analysis::transientFailureName(f))
            return f;
    throw std::invalid_argument("field failure: expected none, multiple-slipping, prolonged-sticking or "
                                "empty but got \"" +
                                text + "\"");
}
} // namespace

std::string csvHeader(ScanKind kind)
{
    return std::string("cell,beta,bowForce,") + (kind == ScanKind::Guettler ? "acceleration" : "bowSpeed") +
           ",regime,transientPeriods,muStatic,jump,firstSlipTime,slipsPerPeriod,pitchCents,failure";
}

std::string formatRow(const CellResult& r)
{
    std::string row = std::to_string(r.cell);
    for (const std::string& field :
         {number(r.beta), number(r.bowForce), number(r.second), std::string(analysis::regimeName(r.regime)),
          optionalNumber(r.transientPeriods), optionalNumber(r.muStatic), optionalNumber(r.jump),
          optionalNumber(r.firstSlipTime), optionalNumber(r.slipsPerPeriod), optionalNumber(r.pitchCents),
          r.failure ? std::string(analysis::transientFailureName(*r.failure)) : std::string()})
    {
        row += ',';
        row += field;
    }
    return row;
}

std::size_t rowCell(const std::string& line)
{
    const std::string first = line.substr(0, line.find(','));
    std::size_t cell = 0;
    const char* last = first.data() + first.size();
    const auto r = std::from_chars(first.data(), last, cell);
    if (first.empty() || r.ec != std::errc() || r.ptr != last)
        throw std::invalid_argument("field cell: expected a cell index but got \"" + first + "\"");
    return cell;
}

CellResult parseRow(const std::string& line)
{
    const auto f = splitFields(line);
    if (f.size() != kFields)
        throw std::invalid_argument("expected " + std::to_string(kFields) +
                                    " comma-separated fields but got " + std::to_string(f.size()));
    CellResult r;
    r.cell = rowCell(line);
    r.beta = parseDouble(f[1], "beta");
    r.bowForce = parseDouble(f[2], "bowForce");
    r.second = parseDouble(f[3], "acceleration/bowSpeed");
    const auto regime = analysis::parseRegime(f[4]);
    if (!regime || f[4] == "silent")
        throw std::invalid_argument("field regime: expected a regime name but got \"" + f[4] + "\"");
    r.regime = *regime;
    r.transientPeriods = parseOptional(f[5], "transientPeriods");
    r.muStatic = parseOptional(f[6], "muStatic");
    r.jump = parseOptional(f[7], "jump");
    r.firstSlipTime = parseOptional(f[8], "firstSlipTime");
    r.slipsPerPeriod = parseOptional(f[9], "slipsPerPeriod");
    r.pitchCents = parseOptional(f[10], "pitchCents");
    r.failure = parseFailure(f[11]);
    return r;
}

} // namespace rosin::scan
