// Child processes without a shell (ChildProcess.h).
#include "lab/scan/ChildProcess.h"

#include <cerrno>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <spawn.h>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace rosin::scan
{

int runProgram(const std::vector<std::string>& argv, bool quiet)
{
    if (argv.empty())
        return -1;
    std::vector<char*> args;
    for (const auto& a : argv)
        args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    if (quiet)
    {
        posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
        posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
    }
    pid_t pid = 0;
    const int started = posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (started != 0)
        return -1;
    int status = 0;
    while (waitpid(pid, &status, 0) == -1)
        if (errno != EINTR)
            return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

bool programAvailable(const std::string& program)
{
    namespace fs = std::filesystem;
    std::error_code ec;
    if (program.find('/') != std::string::npos)
        return access(program.c_str(), X_OK) == 0 && fs::is_regular_file(program, ec);
    const char* path = std::getenv("PATH");
    std::istringstream dirs(path != nullptr ? path : "/usr/bin:/bin");
    for (std::string dir; std::getline(dirs, dir, ':');)
    {
        const fs::path candidate = fs::path(dir.empty() ? "." : dir) / program;
        if (access(candidate.c_str(), X_OK) == 0 && fs::is_regular_file(candidate, ec))
            return true;
    }
    return false;
}

namespace
{
std::vector<std::string> pythonCandidates()
{
    std::vector<std::string> c;
    if (const char* chosen = std::getenv("ROSIN_PYTHON"); chosen != nullptr && *chosen != '\0')
        c.emplace_back(chosen);
    c.emplace_back("/usr/bin/python3");
    c.emplace_back("python3");
    return c;
}
} // namespace

const std::string& figurePython()
{
    static const std::string found = []
    {
        for (const auto& python : pythonCandidates())
            if (programAvailable(python) && runProgram({python, "-c", "import matplotlib, numpy"}, true) == 0)
                return python;
        return std::string();
    }();
    return found;
}

std::string figurePythonCandidates()
{
    std::string text;
    for (const auto& python : pythonCandidates())
        text += (text.empty() ? "" : ", ") + python;
    return text;
}

} // namespace rosin::scan
