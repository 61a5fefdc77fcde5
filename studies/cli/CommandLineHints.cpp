#include "studies/cli/CommandLineHints.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <CLI/CLI.hpp>
#include <charconv>

#include "scene/NameSuggestion.hpp"

namespace granwave {

namespace {

// "--fields", "-o": every name an option of `app` answers to.
std::vector<std::string> optionNames(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::Option* o : app.get_options()) {
    for (const std::string& n : o->get_lnames()) names.push_back("--" + n);
    for (const std::string& n : o->get_snames()) names.push_back("-" + n);
  }
  return names;
}

bool isNumber(const std::string& word) {
  double value = 0;
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  return error == std::errc() && end == word.data() + word.size();
}

// An option word of the command line, without its "=value"; "" for values and positionals.
std::string optionWord(const std::string& arg) {
  if (arg.size() < 2 || arg[0] != '-' || isNumber(arg)) return "";
  return arg.substr(0, arg.find('='));
}

std::string unknownOption(const std::string& word, const CLI::App& command,
                          const CLI::App& program) {
  std::vector<std::string> valid = optionNames(command);
  if (&command != &program)
    for (const std::string& n : optionNames(program)) valid.push_back(n);
  // "-qo": stacked short flags are not a misspelling.
  if (word.size() > 2 && word[1] != '-') return "";
  for (const std::string& n : valid)
    if (n == word) return "";
  const std::string where = &command == &program ? "granwave" : "granwave " + command.get_name();
  return fmt::format("unknown option '{}' of {}{}; see {} --help", word, where,
                     didYouMean(word, valid), where);
}

}  // namespace

std::string misspeltWordMessage(const CLI::App& app, const std::vector<std::string>& args) {
  std::vector<std::string> commands;
  for (const CLI::App* sub : app.get_subcommands({})) commands.push_back(sub->get_name());
  const CLI::App* command = &app;
  std::string first_word;
  for (const std::string& arg : args) {
    if (arg == "--") break;
    if (!optionWord(arg).empty()) continue;
    if (command == &app && first_word.empty()) first_word = arg;
    for (const CLI::App* sub : app.get_subcommands({}))
      if (command == &app && sub->get_name() == arg) command = sub;
  }
  if (command == &app && !first_word.empty())
    return fmt::format("unknown command '{}'{}; commands: {}; see granwave --help", first_word,
                       didYouMean(first_word, commands), fmt::join(commands, ", "));
  for (const std::string& arg : args) {
    if (arg == "--") break;
    const std::string word = optionWord(arg);
    if (word.empty()) continue;
    if (std::string message = unknownOption(word, *command, app); !message.empty()) return message;
  }
  if (command == &app)
    return fmt::format("a command is required: {}; see granwave --help", fmt::join(commands, ", "));
  return "";
}

}  // namespace granwave
