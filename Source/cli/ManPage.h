#pragma once
// `rosin --man`: the man page rosin(1), generated from the commands' manuals (Commands.h), so it says what
// --help says and lists the options the parsers accept. The build writes it to share/man/man1/rosin.1.gz.
#include <string>

namespace rosin::cli
{

/// The page in man(7) markup; `version` goes in its header.
std::string manPage(const std::string& version);

} // namespace rosin::cli
