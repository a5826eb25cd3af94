#pragma once
// `rosin --completion bash`: a bash completion script generated from the commands' option tables (the ones
// their parsers use), so it offers exactly the options and choices rosin accepts. Installed as
// share/bash-completion/completions/rosin.
#include <string>

namespace rosin::cli
{

std::string bashCompletion();

} // namespace rosin::cli
