#include "lab/scan/PartialWriter.h"

#include "lab/scan/CsvRow.h"
#include "lab/scan/ScanError.h"

namespace rosin::scan
{

PartialWriter::PartialWriter(const std::filesystem::path& file, ScanKind kind) : path_(file)
{
    std::error_code ec;
    const bool fresh = !std::filesystem::exists(file, ec) || std::filesystem::file_size(file, ec) == 0;
    file_ = std::fopen(file.c_str(), "ab");
    if (file_ == nullptr)
        throw ScanError(file.string() + ": cannot be opened for writing");
    if (fresh)
        append(csvHeader(kind));
}

PartialWriter::~PartialWriter()
{
    close();
}

void PartialWriter::append(const std::string& row)
{
    if (std::fputs(row.c_str(), file_) < 0 || std::fputc('\n', file_) == EOF || std::fflush(file_) != 0)
        throw ScanError(path_.string() + ": write failed");
}

void PartialWriter::close()
{
    if (file_ != nullptr)
        std::fclose(file_);
    file_ = nullptr;
}

} // namespace rosin::scan
