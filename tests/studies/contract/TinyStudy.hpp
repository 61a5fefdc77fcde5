#pragma once
// The results.h5 of a tiny study (tests/studies/data/tiny-<kind>.toml), for the tests that
// check physics in it. Under ctest the fixture studies_<kind>_tiny_study_runs has made it and
// GRANWAVE_TINY_RESULTS names it (tests/studies/CMakeLists.txt); run alone, the test runs the
// study itself into a scratch directory that is removed afterwards.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "h5/File.hpp"

namespace granwave::testing {

class TinyStudy {
 public:
  explicit TinyStudy(const std::string& kind) {
    const char* made = std::getenv("GRANWAVE_TINY_RESULTS");
    std::string results = made ? made : "";
    if (results.empty()) {
      scratch_ = std::filesystem::temp_directory_path() /
                 ("granwave-tiny-" + kind + "-" + std::to_string(::getpid()));
      std::filesystem::remove_all(scratch_);
      const std::string command = std::string(GRANWAVE_BINARY) + " study " + GRANWAVE_SOURCE_DIR +
                                  "/tests/studies/data/tiny-" + kind + ".toml -o " +
                                  scratch_.string() + " -q -j 2 --no-report";
      if (std::system(command.c_str()) != 0) ADD_FAILURE() << "the study failed: " << command;
      results = (scratch_ / "results.h5").string();
    }
    file_ = std::make_unique<h5::File>(h5::File::openReadOnly(results));
  }
  ~TinyStudy() {
    file_.reset();
    if (!scratch_.empty()) std::filesystem::remove_all(scratch_);
  }
  TinyStudy(const TinyStudy&) = delete;
  TinyStudy& operator=(const TinyStudy&) = delete;

  const h5::File& file() const { return *file_; }
  double value(const std::string& group, const std::string& name) const {
    return file_->readAttribute<double>(group, name);
  }
  std::vector<double> series(const std::string& path) const {
    return file_->readDataset<double>(path);
  }

 private:
  std::filesystem::path scratch_;
  std::unique_ptr<h5::File> file_;
};

// A test suite that opens the tiny study once for all its tests.
template <const char* Kind>
class TinyStudyTest : public ::testing::Test {
 public:
  static void SetUpTestSuite() { study_ = std::make_unique<TinyStudy>(Kind); }
  static void TearDownTestSuite() { study_.reset(); }
  static const TinyStudy& study() { return *study_; }

 private:
  static inline std::unique_ptr<TinyStudy> study_;
};

}  // namespace granwave::testing
