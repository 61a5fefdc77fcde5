#pragma once
// What to tell the user when CLI11 refuses a command line because of a misspelt word: an
// unknown command or option, named with the closest valid one ("unknown command 'simulat'
// (did you mean 'simulate'?); commands: ..."), as scene keys are (scene/NameSuggestion.hpp).
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace granwave {

// The message for a refused command line `args` (without the program name): an unknown
// command or option with the closest valid one, a missing command with the valid ones; "" if
// none of these is wrong (CLI11's own message then says what is).
std::string misspeltWordMessage(const CLI::App& app, const std::vector<std::string>& args);

}  // namespace granwave
