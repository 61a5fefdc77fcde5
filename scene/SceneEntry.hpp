#pragma once
// One key's value in a scene file, as the parser's readers see it (scene/SceneParser.cpp):
// the conversions a reader may ask for, each failing with one line that names the file, the
// key, the value found and what is valid (SceneError).
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "scene/SceneParser.hpp"

namespace granwave::detail {

// A value as written in the file, for error messages.
inline std::string nodeText(const toml::node& node) {
  if (node.is_table()) return "{...}";
  if (const auto* str = node.as_string()) return fmt::format("\"{}\"", str->get());
  std::ostringstream os;
  node.visit([&os](const auto& v) { os << v; });
  std::string text = os.str();
  std::replace(text.begin(), text.end(), '\n', ' ');
  return text;
}

// One key's value as found in the file, with the conversions a reader may ask for.
class Entry {
 public:
  Entry(const toml::node& node, std::string_view key, std::string_view where)
      : node_(node), key_(key), where_(where) {}

  [[noreturn]] void expected(std::string_view what) const {
    throw SceneError(fmt::format("{}: {} = {}: expected {}", where_, key_, nodeText(node_), what));
  }
  double number() const {
    if (auto i = node_.as_integer()) return static_cast<double>(i->get());
    auto f = node_.as_floating_point();
    if (!f || !std::isfinite(f->get())) expected("a finite number");
    return f->get();
  }
  template <class Int>
  Int integer(std::int64_t min = std::numeric_limits<Int>::min()) const {
    auto i = node_.as_integer();
    if (!i) expected("an integer");
    if (i->get() < min || i->get() > std::numeric_limits<Int>::max())
      expected(fmt::format("an integer in [{}, {}]", min, std::numeric_limits<Int>::max()));
    return static_cast<Int>(i->get());
  }
  bool boolean() const {
    auto b = node_.as_boolean();
    if (!b) expected("true or false");
    return b->get();
  }
  const std::string* string() const {
    auto s = node_.as_string();
    return s ? &s->get() : nullptr;
  }
  template <class E>
  E choice(std::initializer_list<std::pair<std::string_view, E>> choices) const {
    if (auto s = string())
      for (const auto& [name, value] : choices)
        if (*s == name) return value;
    std::vector<std::string> names;
    for (const auto& [name, value] : choices) names.push_back(fmt::format("\"{}\"", name));
    expected(fmt::format("one of {}", fmt::join(names, ", ")));
  }

 private:
  const toml::node& node_;
  std::string_view key_, where_;
};

}  // namespace granwave::detail
