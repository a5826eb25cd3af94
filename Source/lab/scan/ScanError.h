#pragma once
// A scan that cannot run or be merged as asked: the message names the file or option and what is wrong
// (a partial file from another scan, a missing shard ...). The command line prints it and exits with 1.
#include <stdexcept>

namespace rosin::scan
{

class ScanError : public std::runtime_error
{
  public:
    using std::runtime_error::runtime_error;
};

} // namespace rosin::scan
