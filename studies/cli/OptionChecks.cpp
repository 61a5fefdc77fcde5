#include "studies/cli/OptionChecks.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string>

#include "files/OutputPath.hpp"

namespace granwave {

CLI::Validator regularInputFile() {
  return CLI::Validator(
      [](std::string& path) -> std::string {
        try {
          files::requireInputFile(path);
        } catch (const files::PathError& e) {
          return e.what();
        }
        return {};
      },
      "FILE", "REGULAR_FILE");
}

std::string quotedValue(const std::string& text) {
  constexpr std::size_t kShown = 60;
  if (text.size() <= kShown) return "'" + text + "'";
  return "'" + text.substr(0, kShown) + "...' (" + std::to_string(text.size()) + " characters)";
}

CLI::Validator finiteNumber() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double value = 0;
        if (CLI::detail::lexical_cast(text, value) && std::isfinite(value)) return {};
        return quotedValue(text) + " is not a finite number";
      },
      "", "FINITE");
}

CLI::Validator numberAbove(double bound, bool inclusive) {
  const std::string rule = (inclusive ? ">= " : "> ") + fmt::format("{:g}", bound);
  return CLI::Validator(
      [bound, inclusive, rule](std::string& text) -> std::string {
        double value = 0;
        if (!CLI::detail::lexical_cast(text, value) || !std::isfinite(value))
          return quotedValue(text) + " is not a finite number";
        if (inclusive ? value >= bound : value > bound) return {};
        return quotedValue(text) + " must be " + rule;
      },
      "NUMBER " + rule, "ABOVE");
}

CLI::Validator autoOrWholeNumber(int lo, int hi) {
  return CLI::Validator(
      [lo, hi](std::string& text) -> std::string {
        if (text == "auto") return {};
        int value = 0;
        if (CLI::detail::lexical_cast(text, value) && value >= lo && value <= hi) return {};
        return fmt::format("{} is not auto or a whole number in [{}, {}]", quotedValue(text), lo,
                           hi);
      },
      fmt::format("auto|{}-{}", lo, hi), "AUTO_OR_WHOLE");
}

}  // namespace granwave
