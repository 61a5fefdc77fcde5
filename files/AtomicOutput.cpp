#include "files/AtomicOutput.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <system_error>

#include "files/OutputPath.hpp"

namespace granwave::files {

AtomicOutput::AtomicOutput(std::string target)
    : target_(std::move(target)), temporary_(temporaryFor(target_)) {
  requireOutputPath(target_);
}

AtomicOutput::~AtomicOutput() {
  if (!committed_) std::remove(temporary_.c_str());
}

void AtomicOutput::commit() {
  // The bytes reach the disk before the rename publishes them; otherwise a power loss right
  // after the rename could leave a complete-looking name over incomplete contents.
  const int fd = ::open(temporary_.c_str(), O_RDONLY);
  const bool synced = fd >= 0 && ::fsync(fd) == 0;
  const int error = errno;
  if (fd >= 0) ::close(fd);
  if (!synced)
    throw std::system_error(error, std::generic_category(), target_ + ": cannot write the file");
  if (std::rename(temporary_.c_str(), target_.c_str()) != 0)
    throw std::system_error(errno, std::generic_category(), target_ + ": cannot publish the file");
  committed_ = true;
}

}  // namespace granwave::files
