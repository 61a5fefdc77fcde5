#include "files/OutputPath.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace granwave::files {
namespace {

namespace fs = std::filesystem;

const char* kindOf(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

fs::path normalised(const std::string& path) {
  std::error_code ec;
  fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
  if (ec) p = fs::absolute(path, ec).lexically_normal();
  return p;
}

}  // namespace

void requireOutputPath(const std::string& path) {
  if (path.empty()) throw PathError("an output path is empty");
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) {
    if (S_ISREG(st.st_mode)) return;
    throw PathError(path + ": is " + kindOf(st.st_mode) +
                    "; an output must be a regular file or a new file name");
  }
  if (errno != ENOENT)
    throw PathError(path + ": cannot be used as an output (" + std::strerror(errno) + ")");
  const fs::path p(path);
  if (!p.has_filename() || p.filename() == "." || p.filename() == "..")
    throw PathError(path +
                    ": names a directory; an output must be a regular file or a new file name");
  // A new name: its directory must exist (the temporary is made there).
  const std::string dir = p.parent_path().empty() ? std::string(".") : p.parent_path().string();
  if (::stat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
    throw PathError(path + ": its directory " + dir + " does not exist");
}

void requireInputFile(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    throw PathError(path + ": cannot be read (" + std::strerror(errno) + ")");
  if (!S_ISREG(st.st_mode))
    throw PathError(path + ": is " + std::string(kindOf(st.st_mode)) +
                    "; an input must be a regular file");
}

bool sameFile(const std::string& a, const std::string& b) {
  struct stat sa {
  }, sb{};
  const bool a_exists = ::stat(a.c_str(), &sa) == 0;
  const bool b_exists = ::stat(b.c_str(), &sb) == 0;
  if (a_exists && b_exists) return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
  if (a_exists != b_exists) return false;
  return normalised(a) == normalised(b);
}

void requireDistinct(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs) {
  for (const NamedPath& out : outputs) requireOutputPath(out.path);
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    for (const NamedPath& in : inputs)
      if (sameFile(outputs[i].path, in.path))
        throw PathError(outputs[i].path + ": the " + outputs[i].role + " would overwrite the " +
                        in.role + " " + in.path);
    for (std::size_t j = 0; j < i; ++j)
      if (sameFile(outputs[i].path, outputs[j].path))
        throw PathError(outputs[i].path + ": the " + outputs[i].role + " and the " +
                        outputs[j].role + " " + outputs[j].path + " would be the same file");
  }
}

std::string temporaryFor(const std::string& target) {
  return target + ".tmp-" + std::to_string(::getpid());
}

}  // namespace granwave::files
