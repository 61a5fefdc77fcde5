#pragma once
// The fixture of the `granwave study` tests (StudyCliTest.cpp: bad and copied study files;
// StudyRerunTest.cpp: whole tiny studies rerun, resumed and interrupted): a scratch directory
// per test, the program run in it, its progress line and run records read back.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace granwave::testing {

namespace fs = std::filesystem;

inline const std::string kTinyStudy =
    GRANWAVE_SOURCE_DIR "/tests/studies/data/tiny-wave-fronts.toml";
inline const std::string kScenes = GRANWAVE_SOURCE_DIR "/scenes";

struct Result {
  int code;
  std::string out, err;
};

// "granwave study: 22 runs, 21 reused from DIR, 1 to do (2 at a time)"
struct Progress {
  int runs = -1, reused = -1, to_do = -1;
};

// Plain parsing: std::regex draws warnings from libstdc++ in the sanitizer build.
inline std::optional<Progress> progress(const std::string& err) {
  const std::string head = "granwave study: ";
  for (std::size_t at = err.find(head); at != std::string::npos; at = err.find(head, at + 1)) {
    const std::string line = err.substr(at + head.size(), err.find('\n', at) - at - head.size());
    Progress p;
    char reused_from[16] = {0};
    if (std::sscanf(line.c_str(), "%d runs, %d %15s", &p.runs, &p.reused, reused_from) != 3 ||
        std::string(reused_from) != "reused")
      continue;
    const auto done = line.find(", ", line.find(" reused from "));
    if (done == std::string::npos || std::sscanf(line.c_str() + done, ", %d to do", &p.to_do) != 1)
      continue;
    return p;
  }
  return std::nullopt;
}

class StudyCli : public ::testing::Test {
 protected:
  void SetUp() override {
    // Parameterised tests are named "Test/Case": one directory level, so TearDown removes it.
    std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    std::replace(name.begin(), name.end(), '/', '_');
    dir_ = fs::temp_directory_path() /
           ("granwave_study_cli_" + std::to_string(::getpid()) + "_" + name);
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    binary_time_ = fs::last_write_time(GRANWAVE_BINARY);
  }
  // The run cache is keyed on the build of granwave (a hash of the executable): if someone
  // relinks it while a test runs (a shared working tree), every run is redone by design.
  bool binaryRebuilt() const { return fs::last_write_time(GRANWAVE_BINARY) != binary_time_; }
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(dir_);  // kept for a look when something failed
  }

  std::string write(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    std::ofstream(p) << text;
    return p.string();
  }
  static std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  }
  // True once `file` contains `text`; false after `limit`.
  static bool waitForText(const fs::path& file, const std::string& text,
                          std::chrono::seconds limit) {
    const auto end = std::chrono::steady_clock::now() + limit;
    while (slurp(file).find(text) == std::string::npos) {
      if (std::chrono::steady_clock::now() > end) return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return true;
  }
  Result run(const std::string& args) {
    const std::string cmd =
        "cd '" + dir_.string() + "' && '" GRANWAVE_BINARY "' " + args + " > out.txt 2> err.txt";
    const int status = std::system(cmd.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(dir_ / "out.txt"),
            slurp(dir_ / "err.txt")};
  }
  // The records (.done files) in OUTDIR/runs.
  std::vector<fs::path> records(const std::string& outdir) const {
    std::vector<fs::path> out;
    const fs::path runs = dir_ / outdir / "runs";
    if (!fs::is_directory(runs)) return out;
    for (const auto& e : fs::directory_iterator(runs))
      if (e.path().extension() == ".done") out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
  }
  fs::path dir_;
  fs::file_time_type binary_time_;
};

inline constexpr const char* kRebuilt =
    "granwave was rebuilt while this test ran; the run cache is keyed on the build, so "
    "reuse cannot be checked";

// A study file with `replace` substituted for the line starting with `key`.
inline std::string studyWith(const std::string& path, const std::string& key,
                             const std::string& replace) {
  std::ifstream in(path);
  std::string text, line;
  while (std::getline(in, line)) {
    if (line.starts_with(key)) line = replace;
    // The copy lives elsewhere: scene paths become absolute.
    const std::string rel = "\"../../../scenes/";
    if (const auto at = line.find(rel); at != std::string::npos)
      line.replace(at, rel.size(), "\"" + kScenes + "/");
    text += line + "\n";
  }
  return text;
}

// The tiny wave-fronts study, the tiny stability sweep, resp. the tiny continuum-sensitivity
// study, with one line replaced.
inline std::string tinyWith(const std::string& key, const std::string& replace) {
  return studyWith(kTinyStudy, key, replace);
}
inline std::string tinyStabilityWith(const std::string& key, const std::string& replace) {
  return studyWith(GRANWAVE_SOURCE_DIR "/tests/studies/data/tiny-stability.toml", key, replace);
}
inline std::string tinySensitivityWith(const std::string& key, const std::string& replace) {
  return studyWith(GRANWAVE_SOURCE_DIR "/tests/studies/data/tiny-continuum-sensitivity.toml", key,
                   replace);
}

}  // namespace granwave::testing
