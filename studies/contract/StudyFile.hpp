#pragma once
// A study file (TOML; docs/studies.md): [study] kind and jobs, then the sections of its
// kind. Every key read through this class is recorded, so that after a study has read its
// keys any key left over is reported as unknown, with the valid ones, before anything runs.
#include <toml++/toml.h>

#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace granwave {

class StudyError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class StudyFile {
 public:
  // Throws StudyError (file missing, TOML syntax, no [study] kind).
  static StudyFile load(const std::string& path);

  const std::string& path() const { return path_; }
  const std::string& text() const { return text_; }
  const std::string& kind() const { return kind_; }

  double number(std::string_view section, std::string_view key, double fallback);
  int integer(std::string_view section, std::string_view key, int fallback);
  bool boolean(std::string_view section, std::string_view key, bool fallback);
  std::string string(std::string_view section, std::string_view key, std::string fallback);
  std::vector<double> numbers(std::string_view section, std::string_view key,
                              std::vector<double> fallback);
  std::vector<int> integers(std::string_view section, std::string_view key,
                            std::vector<int> fallback);
  std::vector<std::string> strings(std::string_view section, std::string_view key,
                                   std::vector<std::string> fallback);
  // A scene (or other input) file the study file names: an absolute path, or a path relative
  // to the study file's directory, else relative to the study files installed with the
  // program (share/granwave/studies, so "../scenes/paper-dry.toml" reaches the shipped
  // scenes from a study file copied anywhere). StudyError listing both places if neither has it.
  std::string scenePath(std::string_view section, std::string_view key, std::string fallback);

  // True if the file has the section (whatever it holds).
  bool hasSection(std::string_view section) const { return table_[section].is_table(); }
  // Throws StudyError naming the first key or section that no read asked for.
  void rejectUnknownKeys() const;
  // "STUDY.toml: [section] key = value: what"
  [[noreturn]] void fail(std::string_view section, std::string_view key,
                         const std::string& what) const;

 private:
  const toml::node* find(std::string_view section, std::string_view key);
  std::string path_, text_, kind_;
  toml::table table_;
  std::map<std::string, std::set<std::string>> known_;  // section -> keys read
};

}  // namespace granwave
