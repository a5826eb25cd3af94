// The `rosin` executable: everything lives in rosin_cli so the tests can run it in-process.
#include <iostream>
#include <string>
#include <vector>

#include "cli/Dispatcher.h"

int main(int argc, char* argv[])
{
    const std::vector<std::string> args(argv + 1, argv + argc);
    return rosin::cli::run(args, std::cout, std::cerr);
}
