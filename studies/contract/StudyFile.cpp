#include "studies/contract/StudyFile.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "scene/NameSuggestion.hpp"
#include "studies/installation/InstalledFiles.hpp"

namespace granwave {

StudyFile StudyFile::load(const std::string& path) {
  StudyFile f;
  f.path_ = path;
  std::ifstream in(path);
  if (!in) throw StudyError(fmt::format("{}: cannot open study file", path));
  std::ostringstream s;
  s << in.rdbuf();
  f.text_ = s.str();
  try {
    f.table_ = toml::parse(f.text_, path);
  } catch (const toml::parse_error& e) {
    throw StudyError(fmt::format("{}:{}:{}: TOML syntax error: {}", path, e.source().begin.line,
                                 e.source().begin.column, e.description()));
  }
  f.kind_ = f.string("study", "kind", "");
  if (f.kind_.empty())
    throw StudyError(
        fmt::format("{}: [study] kind is missing; valid kinds: wave-fronts, "
                    "sound-speed, effective-restitution, momentum-transfer, stability, readings",
                    path));
  return f;
}

const toml::node* StudyFile::find(std::string_view section, std::string_view key) {
  known_[std::string(section)].insert(std::string(key));
  const toml::table* t = table_[section].as_table();
  if (!t) return nullptr;
  return t->get(key);
}

void StudyFile::fail(std::string_view section, std::string_view key,
                     const std::string& what) const {
  const toml::table* t = table_[section].as_table();
  const toml::node* n = t ? t->get(key) : nullptr;
  std::ostringstream v;
  if (n) n->visit([&](const auto& x) { v << x; });
  throw StudyError(n ? fmt::format("{}: [{}] {} = {}: {}", path_, section, key, v.str(), what)
                     : fmt::format("{}: [{}] {}: {}", path_, section, key, what));
}

double StudyFile::number(std::string_view section, std::string_view key, double fallback) {
  const toml::node* n = find(section, key);
  if (!n) return fallback;
  if (auto v = n->value<double>()) return *v;
  fail(section, key, "expected a number");
}

int StudyFile::integer(std::string_view section, std::string_view key, int fallback) {
  const toml::node* n = find(section, key);
  if (!n) return fallback;
  if (n->is_integer()) {
    const std::int64_t v = *n->value<std::int64_t>();
    if (v >= std::numeric_limits<int>::min() && v <= std::numeric_limits<int>::max())
      return static_cast<int>(v);
  }
  fail(section, key, "expected an integer (32-bit)");
}

bool StudyFile::boolean(std::string_view section, std::string_view key, bool fallback) {
  const toml::node* n = find(section, key);
  if (!n) return fallback;
  if (n->is_boolean()) return *n->value<bool>();
  fail(section, key, "expected true or false");
}

std::string StudyFile::string(std::string_view section, std::string_view key,
                              std::string fallback) {
  const toml::node* n = find(section, key);
  if (!n) return fallback;
  if (auto v = n->value<std::string>()) return *v;
  fail(section, key, "expected a string");
}

std::vector<double> StudyFile::numbers(std::string_view section, std::string_view key,
                                       std::vector<double> fallback) {
  const toml::node* n = find(section, key);
  if (!n) return fallback;
  const toml::array* a = n->as_array();
  if (!a || a->empty()) fail(section, key, "expected a non-empty array of numbers");
  std::vector<double> out;
  for (const toml::node& e : *a) {
    auto v = e.value<double>();
    if (!v) fail(section, key, "expected a non-empty array of numbers");
    out.push_back(*v);
  }
  return out;
}

std::vector<int> StudyFile::integers(std::string_view section, std::string_view key,
                                     std::vector<int> fallback) {
  const toml::node* n = find(section, key);
  if (!n) return fallback;
  const toml::array* a = n->as_array();
  if (!a || a->empty()) fail(section, key, "expected a non-empty array of integers");
  std::vector<int> out;
  for (const toml::node& e : *a) {
    const std::int64_t v = e.is_integer() ? *e.value<std::int64_t>() : 0;
    if (!e.is_integer() || v < std::numeric_limits<int>::min() ||
        v > std::numeric_limits<int>::max())
      fail(section, key, "expected a non-empty array of (32-bit) integers");
    out.push_back(static_cast<int>(v));
  }
  return out;
}

std::vector<std::string> StudyFile::strings(std::string_view section, std::string_view key,
                                            std::vector<std::string> fallback) {
  const toml::node* n = find(section, key);
  if (!n) return fallback;
  const toml::array* a = n->as_array();
  if (!a) fail(section, key, "expected an array of strings");
  std::vector<std::string> out;
  for (const toml::node& e : *a) {
    auto v = e.value<std::string>();
    if (!v) fail(section, key, "expected an array of strings");
    out.push_back(*v);
  }
  return out;
}

std::string StudyFile::scenePath(std::string_view section, std::string_view key,
                                 std::string fallback) {
  const std::filesystem::path given(string(section, key, std::move(fallback)));
  std::vector<std::filesystem::path> places{given};
  if (given.is_relative())
    places = {std::filesystem::path(path_).parent_path() / given,
              std::filesystem::path(installedFile("studies")) / given};
  std::string looked;
  for (const std::filesystem::path& place : places) {
    if (std::filesystem::is_regular_file(place)) return place.lexically_normal().string();
    looked += (looked.empty() ? "" : " and ") + place.lexically_normal().string();
  }
  fail(section, key, fmt::format("no such file (looked in {})", looked));
}

void StudyFile::rejectUnknownKeys() const {
  auto list = [](const auto& names) {
    std::string s;
    for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
    return s;
  };
  std::set<std::string> sections;
  for (const auto& [name, keys] : known_) sections.insert(name);
  for (const auto& [name, node] : table_) {
    const std::string section(name.str());
    const toml::table* t = node.as_table();
    if (!t || !known_.count(section))
      throw StudyError(fmt::format(
          "{}: unknown section [{}]{} for a {} study; valid sections: {}", path_, section,
          didYouMean(section, {sections.begin(), sections.end()}), kind_, list(sections)));
    const auto& keys = known_.at(section);
    for (const auto& [key, value] : *t) {
      if (!keys.count(std::string(key.str())))
        throw StudyError(fmt::format(
            "{}: unknown key '{}.{}'{}; valid keys in [{}]: {}", path_, section, key.str(),
            didYouMean(key.str(), {keys.begin(), keys.end()}), section, list(keys)));
    }
  }
}

}  // namespace granwave
