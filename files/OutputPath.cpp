#include "files/OutputPath.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "files/SideFiles.hpp"

namespace granwave::files {
namespace {

namespace fs = std::filesystem;

const char* kindOf(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISSOCK(mode)) return "a socket";
  if (S_ISREG(mode)) return "a regular file";
  return "not a regular file";
}

fs::path normalised(const std::string& path) {
  std::error_code ec;
  fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
  if (ec) p = fs::absolute(path, ec).lexically_normal();
  return p;
}

// The longest suffix temporaryFor adds: ".tmp-" and a process id (at most 4194304, proc(5)).
constexpr std::size_t kTemporarySuffix = 12;

// The temporary is made in the output's directory and renamed over it: the directory must
// take a new name of that length and a file from this process.
void requireWritableDirectory(const std::string& path, const std::string& dir) {
  const long name_max = ::pathconf(dir.c_str(), _PC_NAME_MAX);
  const std::size_t length = fs::path(path).filename().string().size();
  if (name_max > 0 && length + kTemporarySuffix > static_cast<std::size_t>(name_max))
    throw PathError(path.substr(0, 60) + "...: a file name of " + std::to_string(length) +
                    " characters is too long for its directory (at most " +
                    std::to_string(static_cast<std::size_t>(name_max) - kTemporarySuffix) +
                    " here)");
  if (::access(dir.c_str(), W_OK | X_OK) != 0)
    throw PathError(path + ": cannot write in its directory " + dir + " (" + std::strerror(errno) +
                    ")");
}

}  // namespace

void requireOutputPath(const std::string& path) {
  if (path.empty()) throw PathError("an output path is empty");
  const fs::path p(path);
  const std::string dir = p.parent_path().empty() ? std::string(".") : p.parent_path().string();
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) {
    if (!S_ISREG(st.st_mode))
      throw PathError(path + ": is " + kindOf(st.st_mode) +
                      "; an output must be a regular file or a new file name");
    requireWritableDirectory(path, dir);
    return;
  }
  if (errno != ENOENT && errno != ENAMETOOLONG)
    throw PathError(path + ": cannot be used as an output (" + std::strerror(errno) + ")");
  if (!p.has_filename() || p.filename() == "." || p.filename() == "..")
    throw PathError(path +
                    ": names a directory; an output must be a regular file or a new file name");
  // A new name: its directory must exist (the temporary is made there).
  if (::stat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
    throw PathError(path + ": its directory " + dir + " does not exist");
  requireWritableDirectory(path, dir);
}

void requireOutputDirectory(const std::string& path, const std::string& option) {
  if (path.empty()) throw PathError(option + ": the output directory is empty");
  fs::path existing = fs::absolute(path).lexically_normal();
  struct stat st {};
  bool is_new = false;
  while (::stat(existing.c_str(), &st) != 0) {
    if (errno == ENAMETOOLONG)
      throw PathError(path.substr(0, 60) + "...: " + option + " names too long a path");
    if (errno != ENOENT && errno != ENOTDIR)
      throw PathError(path + ": cannot be used as the " + option + " directory (" +
                      std::strerror(errno) + ")");
    is_new = true;
    if (!existing.has_relative_path()) break;
    existing = existing.parent_path();
  }
  if (!S_ISDIR(st.st_mode))
    throw PathError((is_new ? existing.string() : path) + ": is " + kindOf(st.st_mode) + "; " +
                    option + " must name a directory or a new directory name");
  if (::access(existing.c_str(), W_OK | X_OK) != 0)
    throw PathError(path + ": cannot write in " + existing.string() + " (" + std::strerror(errno) +
                    ")");
  long name_max = ::pathconf(existing.c_str(), _PC_NAME_MAX);
  for (const fs::path& part : fs::path(path))
    if (name_max > 0 && part.string().size() > static_cast<std::size_t>(name_max))
      throw PathError(path.substr(0, 60) + "...: a directory name of " +
                      std::to_string(part.string().size()) + " characters is too long (at most " +
                      std::to_string(name_max) + ")");
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

// A file the user named must not be one granwave makes beside an output and removes.
void requireNoSideFile(const std::vector<NamedPath>& inputs,
                       const std::vector<NamedPath>& outputs) {
  for (const NamedPath& out : outputs) {
    if (out.derived) continue;
    const auto check = [&out](const NamedPath& named) {
      if (named.derived || &named == &out) return;
      if (const char* kind = sideFileKind(named.path, out.path))
        throw PathError(named.path + ": the " + named.role + " is named like the " + kind +
                        " granwave makes beside the " + out.role + " " + out.path +
                        " (and removes); name it otherwise");
    };
    for (const NamedPath& in : inputs) check(in);
    for (const NamedPath& other : outputs) check(other);
  }
}

void requireDistinct(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs) {
  for (const NamedPath& out : outputs) requireOutputPath(out.path);
  requireNoSideFile(inputs, outputs);
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
