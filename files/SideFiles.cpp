#include "files/SideFiles.hpp"

#include <filesystem>
#include <string_view>

namespace granwave::files {
namespace {

namespace fs = std::filesystem;

bool allDigits(std::string_view s) {
  return !s.empty() && s.find_first_not_of("0123456789") == std::string_view::npos;
}

// The directory a name lives in, with its symbolic links resolved; the name itself is not
// followed (removing a side file removes the name, not what a link points at).
fs::path directoryOf(const std::string& path) {
  std::error_code ec;
  const fs::path absolute = fs::absolute(path, ec).lexically_normal();
  fs::path dir = fs::weakly_canonical(absolute.parent_path(), ec);
  if (ec) dir = absolute.parent_path();
  return dir;
}

}  // namespace

bool isTemporaryOf(const std::string& name, const std::string& prefix, long& pid) {
  if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) return false;
  const std::string_view rest = std::string_view(name).substr(prefix.size());
  const std::size_t mark = rest.rfind(".tmp-");
  if (rest.front() != '.' || mark == std::string_view::npos) return false;
  const std::string_view digits = rest.substr(mark + 5);
  if (!allDigits(digits) || digits.size() > 9) return false;
  pid = std::stol(std::string(digits));
  return true;
}

bool isCheckpointCopyOf(const std::string& name, const std::string& prefix) {
  const std::string head = prefix + ".checkpoint-";
  const std::string tail = ".h5md";
  if (name.size() <= head.size() + tail.size() || name.compare(0, head.size(), head) != 0 ||
      !name.ends_with(tail))
    return false;
  return allDigits(
      std::string_view(name).substr(head.size(), name.size() - head.size() - tail.size()));
}

const char* sideFileKind(const std::string& candidate, const std::string& output) {
  const std::string name = fs::path(candidate).filename().string();
  const std::string prefix = fs::path(output).filename().string();
  if (name.empty() || prefix.empty() || name.size() <= prefix.size()) return nullptr;
  if (name.compare(0, prefix.size(), prefix) != 0) return nullptr;
  std::error_code ec;
  const fs::path a = directoryOf(candidate), b = directoryOf(output);
  if (!(a == b || fs::equivalent(a, b, ec))) return nullptr;
  const std::string_view rest = std::string_view(name).substr(prefix.size());
  long pid = 0;
  if (isTemporaryOf(name, prefix, pid)) return "temporary";
  if (rest == ".lock") return "lock file";
  if (rest == ".checkpoint") return "checkpoint";
  if (isCheckpointCopyOf(name, prefix)) return "checkpoint copy";
  if (rest == ".interrupted") return "partial run file";
  return nullptr;
}

}  // namespace granwave::files
