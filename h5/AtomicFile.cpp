#include "h5/AtomicFile.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "files/OutputPath.hpp"
#include "h5/H5Error.hpp"

namespace granwave::h5 {
namespace {

// Forces the bytes to disk before the rename publishes them; otherwise a power loss right
// after the rename could leave a complete-looking name over incomplete contents.
void syncPath(const std::string& path, int flags) {
  const int fd = ::open(path.c_str(), flags);
  if (fd < 0) return;
  (void)::fsync(fd);
  ::close(fd);
}

// A target that is not a regular file or a new name in an existing directory (a device, a
// directory) is refused before anything is written: the rename would replace it.
void requireOutputPath(const std::string& target) {
  try {
    files::requireOutputPath(target);
  } catch (const files::PathError& e) {
    throw H5Error(e.what());
  }
}

// HDF5 may leave a partial file behind when creation fails half-way.
File createOrRemove(const std::string& temporary, const std::string& target) {
  requireOutputPath(target);
  try {
    return File::create(temporary, target);
  } catch (...) {
    std::remove(temporary.c_str());
    throw;
  }
}

File copyAndOpen(const std::string& from, const std::string& temporary, const std::string& target) {
  requireOutputPath(target);
  std::error_code ec;
  std::filesystem::copy_file(from, temporary, std::filesystem::copy_options::overwrite_existing,
                             ec);
  if (ec) {
    std::remove(temporary.c_str());
    throw H5Error(from + ": cannot copy to " + temporary + " (" + ec.message() + ")");
  }
  try {
    return File::openReadWrite(temporary, target);
  } catch (...) {
    std::remove(temporary.c_str());
    throw;
  }
}

std::string directoryOf(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

}  // namespace

AtomicFile::AtomicFile(std::string target)
    : target_(std::move(target)),
      temporary_(files::temporaryFor(target_)),
      file_(createOrRemove(temporary_, target_)) {}

AtomicFile::AtomicFile(std::string target, const std::string& continue_from)
    : target_(std::move(target)),
      temporary_(files::temporaryFor(target_)),
      file_(copyAndOpen(continue_from, temporary_, target_)) {}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  try {
    file_.close();
  } catch (const H5Error&) {
    // The contents are being discarded; a failure to write them back is moot.
  }
  std::remove(temporary_.c_str());
}

void AtomicFile::commitTo(const std::string& path) {
  if (committed_) throw H5Error(target_ + ": already committed");
  file_.flush();
  file_.close();
  syncPath(temporary_, O_RDONLY);
  if (std::rename(temporary_.c_str(), path.c_str()) != 0) {
    throw H5Error(target_ + ": cannot rename " + temporary_ + " to " + path + " (" +
                  std::strerror(errno) + ")");
  }
  committed_ = true;
  syncPath(directoryOf(path), O_RDONLY | O_DIRECTORY);
}

void AtomicFile::copyTo(const std::string& path) {
  if (committed_) throw H5Error(target_ + ": already committed");
  file_.flush();
  const std::string partial = files::temporaryFor(path);
  std::error_code ec;
  std::filesystem::copy_file(temporary_, partial, std::filesystem::copy_options::overwrite_existing,
                             ec);
  if (ec) {
    std::remove(partial.c_str());
    throw H5Error(target_ + ": cannot copy to " + partial + " (" + ec.message() + ")");
  }
  syncPath(partial, O_RDONLY);
  if (std::rename(partial.c_str(), path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    std::remove(partial.c_str());
    throw H5Error(target_ + ": cannot rename " + partial + " to " + path + " (" + reason + ")");
  }
  syncPath(directoryOf(path), O_RDONLY | O_DIRECTORY);
}

}  // namespace granwave::h5
