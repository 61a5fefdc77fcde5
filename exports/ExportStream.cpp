#include "exports/ExportStream.hpp"

#include <cerrno>
#include <system_error>

namespace granwave {

ExportStream::ExportStream(const std::string& path, std::string target, bool binary)
    : out_(path, binary ? std::ios::binary | std::ios::trunc : std::ios::trunc),
      target_(std::move(target)) {
  check();
}

void ExportStream::check() const {
  if (!out_)
    throw std::system_error(errno ? errno : EIO, std::generic_category(),
                            target_ + ": cannot write the export");
}

void ExportStream::close() {
  out_.flush();
  check();
  out_.close();
  check();
}

}  // namespace granwave
