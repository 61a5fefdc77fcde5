// The command line itself: a mistyped command or option is named with the closest valid one
// (as scene keys are), every --help entry that takes a value shows its default, and
// `granwave --version` names the version and the source commit it was built from.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "tests/h5/ScratchDir.hpp"

namespace {

struct Result {
  int code;
  std::string out, err;
};

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

class CommandLine : public ::testing::Test {
 protected:
  Result run(const std::string& args) const {
    const std::string cmd = "cd '" + dir_.path().string() + "' && '" GRANWAVE_BINARY "' " + args +
                            " > out.txt 2> err.txt";
    const int status = std::system(cmd.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(dir_.path() / "out.txt"),
            slurp(dir_.path() / "err.txt")};
  }
  // Exit 2 and exactly one line on stderr containing `words`.
  void expectOneLine(const std::string& args, const std::string& words) const {
    const Result r = run(args);
    EXPECT_EQ(r.code, 2) << args;
    EXPECT_NE(r.err.find(words), std::string::npos) << args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  granwave::testing::ScratchDir dir_;
};

TEST_F(CommandLine, MistypedCommandIsNamedWithTheClosestOne) {
  expectOneLine("simulat scene.toml", "unknown command 'simulat' (did you mean 'simulate'?)");
  expectOneLine("studdy s.toml",
                "(did you mean 'study'?); commands: simulate, fields, hydro, "
                "study, export");
  expectOneLine("frobnicate", "unknown command 'frobnicate'; commands:");
}

TEST_F(CommandLine, MistypedOptionIsNamedWithTheClosestOptionOfItsCommand) {
  std::ofstream(dir_.path() / "s.toml") << "[contact]\nrestitution = \"dry\"\n";
  expectOneLine("simulate s.toml --fileds f.h5",
                "unknown option '--fileds' of granwave simulate (did you mean '--fields'?)");
  expectOneLine("simulate s.toml --fileds=f.h5", "(did you mean '--fields'?)");
  expectOneLine("study s.toml --no-reprot", "(did you mean '--no-report'?)");
  expectOneLine("--verison", "unknown option '--verison' of granwave (did you mean '--version'?)");
  EXPECT_FALSE(std::filesystem::exists(dir_.path() / "s.h5"));
}

TEST_F(CommandLine, MissingCommandListsTheCommands) {
  expectOneLine("", "a command is required: simulate, fields, hydro, study, export");
}

TEST_F(CommandLine, OtherRefusalsKeepTheParsersOwnMessage) {
  std::ofstream(dir_.path() / "r.h5") << "x";
  // A negative number is a value, not an option; the range check says what is wrong.
  const Result r = run("fields r.h5 --blocks -3");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err.find("unknown option"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--blocks"), std::string::npos) << r.err;
}

// Every option that takes a value shows its default ("=value" or "default: ..." in its text);
// flags are off unless given.
TEST_F(CommandLine, EveryHelpEntryThatTakesAValueShowsItsDefault) {
  for (const std::string command : {"", "simulate", "fields", "hydro", "study", "export"}) {
    const Result r = run(command + " --help");
    ASSERT_EQ(r.code, 0) << command;
    const std::string options = r.out.substr(r.out.find("Options:"));
    std::vector<std::string> entries;
    std::istringstream lines(options);
    for (std::string line; std::getline(lines, line);) {
      if (line.rfind("  -", 0) == 0)
        entries.push_back(line);
      else if (line.rfind("   ", 0) == 0 && !entries.empty())
        entries.back() += line;
    }
    ASSERT_FALSE(entries.empty()) << command;
    for (const std::string& entry : entries) {
      const std::string signature = entry.substr(2, entry.find("  ", 2) - 2);
      const bool takes_value = signature.find(' ') != std::string::npos;
      const bool shows_default =
          signature.find('=') != std::string::npos || entry.find("default") != std::string::npos;
      EXPECT_TRUE(!takes_value || shows_default) << "granwave " << command << ": " << entry;
    }
  }
}

TEST_F(CommandLine, VersionNamesTheVersionAndTheSourceCommit) {
  const Result r = run("--version");
  ASSERT_EQ(r.code, 0) << r.err;
  std::smatch m;
  ASSERT_TRUE(std::regex_match(
      r.out, m,
      std::regex("granwave [0-9]+\\.[0-9]+\\.[0-9]+ \\(source commit (([0-9a-f]{40}), (clean|with "
                 "uncommitted changes)|unknown)\\)\n")))
      << r.out;
  // The commit recorded at build time beside the program (share/granwave/source-commit).
  const std::filesystem::path record =
      std::filesystem::path(GRANWAVE_BINARY).parent_path().parent_path() / "share" / "granwave" /
      "source-commit";
  std::istringstream recorded(slurp(record));
  std::string commit;
  recorded >> commit;
  EXPECT_EQ(m[2].matched ? m[2].str() : std::string("unknown"), commit);
}

}  // namespace
