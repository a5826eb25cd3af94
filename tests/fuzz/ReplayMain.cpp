// Without libFuzzer (the normal build, gcc): runs a fuzz target over every file of the given folders or
// files, so CTest replays the committed corpus (tests/fuzz/corpus) on every build, under the sanitizers in
// the sanitizer job. A finding aborts, which fails the test.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <vector>

#include "fuzz/FuzzTarget.h"

namespace
{

int replay(const std::filesystem::path& file)
{
    std::ifstream in(file, std::ios::binary);
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
}

} // namespace

int main(int argc, char** argv)
{
    std::vector<std::filesystem::path> files;
    for (int i = 1; i < argc; ++i)
    {
        const std::filesystem::path arg(argv[i]);
        if (std::filesystem::is_directory(arg))
        {
            for (const auto& entry : std::filesystem::directory_iterator(arg))
                if (entry.is_regular_file())
                    files.push_back(entry.path());
        }
        else
            files.push_back(arg);
    }
    std::sort(files.begin(), files.end());
    if (files.empty())
    {
        std::cerr << "no corpus files given\n";
        return 2;
    }
    for (const auto& file : files)
        replay(file);
    std::cout << "replayed " << files.size() << " inputs\n";
    return 0;
}
