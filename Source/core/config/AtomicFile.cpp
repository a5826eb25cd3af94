#include "core/config/AtomicFile.h"

#include <fstream>
#include <system_error>
#include <unistd.h>

#include "core/config/ConfigError.h"

namespace rosin::config
{

namespace fs = std::filesystem;

void writeFileAtomically(const fs::path& file, const std::string& text)
{
    // The process id keeps two runs writing the same file from sharing a temporary.
    fs::path temporary = file;
    temporary += ".tmp-" + std::to_string(::getpid());
    std::error_code ec;
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out << text;
        out.close();
        if (!out)
        {
            fs::remove(temporary, ec);
            throw ConfigError(file.string(), "", "a writable file",
                              "a write error (is the folder there? disk full?)");
        }
    }
    fs::rename(temporary, file, ec);
    if (ec)
    {
        const std::string reason = ec.message();
        fs::remove(temporary, ec);
        throw ConfigError(file.string(), "", "a writable file", reason);
    }
}

} // namespace rosin::config
