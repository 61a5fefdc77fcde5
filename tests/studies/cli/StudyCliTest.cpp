// `granwave study` end to end: bad study files (one-line error, exit code 2, nothing
// written), a tiny wave-fronts study (results.h5, report.html), the run cache (a rerun reuses
// every run and gives the same results; a run whose record is deleted is the only one redone),
// and an interrupt (exit 130, finished runs kept, the same command resumes).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "h5/File.hpp"

extern char** environ;

namespace fs = std::filesystem;

namespace {

const std::string kTinyStudy = GRANWAVE_SOURCE_DIR "/tests/studies/data/tiny-wave-fronts.toml";
const std::string kScenes = GRANWAVE_SOURCE_DIR "/scenes";

struct Result {
  int code;
  std::string out, err;
};

// "granwave study: 22 runs, 21 reused from DIR, 1 to do (2 at a time)"
struct Progress {
  int runs = -1, reused = -1, to_do = -1;
};

// Plain parsing: std::regex draws warnings from libstdc++ in the sanitizer build.
std::optional<Progress> progress(const std::string& err) {
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

constexpr const char* kRebuilt =
    "granwave was rebuilt while this test ran; the run cache is keyed on the build, so "
    "reuse cannot be checked";

// A study file with `replace` substituted for the line starting with `key`.
std::string studyWith(const std::string& path, const std::string& key, const std::string& replace) {
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

// The tiny wave-fronts study, resp. the tiny stability sweep, with one line replaced.
std::string tinyWith(const std::string& key, const std::string& replace) {
  return studyWith(kTinyStudy, key, replace);
}
std::string tinyStabilityWith(const std::string& key, const std::string& replace) {
  return studyWith(GRANWAVE_SOURCE_DIR "/tests/studies/data/tiny-stability.toml", key, replace);
}

struct BadStudy {
  const char* name;
  std::string text;
  const char* must_mention;
};

// Test names and failure messages show the case, not the struct's bytes.
void PrintTo(const BadStudy& b, std::ostream* os) { *os << b.name; }

class StudyCliBadFile : public StudyCli, public ::testing::WithParamInterface<BadStudy> {};

}  // namespace

TEST_P(StudyCliBadFile, FailsWithOneLineErrorExitCode2AndWritesNothing) {
  const BadStudy& b = GetParam();
  const std::string study = write("bad.toml", b.text);
  const Result r = run("study -q " + study + " -o out");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(r.err.starts_with("granwave: ")) << r.err;
  EXPECT_NE(r.err.find("bad.toml"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(b.must_mention), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_FALSE(fs::exists(dir_ / "out")) << "the output directory was created";
  EXPECT_FALSE(fs::exists(dir_ / "out" / "results.h5"));
}

INSTANTIATE_TEST_SUITE_P(
    EveryClass, StudyCliBadFile,
    ::testing::Values(
        BadStudy{"UnknownKind", tinyWith("kind", "kind = \"wave-front\""), "unknown study kind"},
        BadStudy{"MissingKind", tinyWith("kind", ""), "[study] kind is missing"},
        BadStudy{"UnknownKey", tinyWith("seeds", "seeds = [1]\nsedes = [2]"),
                 "unknown key 'particles.sedes' (did you mean 'seeds'?)"},
        BadStudy{"UnknownSection", tinyWith("[cost]", "[costs]"),
                 "unknown section [costs] (did you mean 'cost'?)"},
        BadStudy{"WrongType", tinyWith("seeds", "seeds = 1"), "[particles] seeds"},
        BadStudy{"MissingSceneFile", tinyWith("wet", "wet = \"nosuch-scene.toml\""),
                 "wet = 'nosuch-scene.toml': no such file (looked in "},
        BadStudy{"SceneOverrideRejected", tinyWith("set", "set = [\"drive.gama=4\"]"),
                 "drive.gama"},
        BadStudy{"MalformedToml", tinyWith("[sweep]", "[sweep"), "TOML syntax error"},
        BadStudy{"NegativeJobs", tinyWith("kind", "kind = \"wave-fronts\"\njobs = -3"),
                 "[study] jobs"},
        BadStudy{"StabilityRepeatedSeed", tinyStabilityWith("seeds", "seeds = [1, 1]"),
                 "[particles] seeds"},
        BadStudy{"StabilitySingleSeedKeyIsUnknown", tinyStabilityWith("seeds", "seed = 1"),
                 "unknown key 'particles.seed'"},
        BadStudy{"StabilityRepeatedGamma", tinyStabilityWith("gammas", "gammas = [3.0, 3.0]"),
                 "[grid] gammas"},
        BadStudy{"StabilityTooFewCycles", tinyStabilityWith("cycles", "cycles = 10"),
                 "[particles] cycles"}),
    [](const auto& info) { return std::string(info.param.name); });

// A study file copied out of the repository names the scenes as the shipped ones do
// (../scenes/paper-*.toml): not beside the copy, they are found among the study files shipped
// beside the program (build/share/granwave). The study then stops at the next check, an
// unknown section, which is read after the scenes.
TEST_F(StudyCli, CopiedStudyFileFindsTheShippedScenes) {
  std::string text = tinyWith("dry", "dry = \"../scenes/paper-dry.toml\"");
  text = studyWith(write("copy.toml", text), "wet", "wet = \"../scenes/paper-wet.toml\"");
  const Result r = run("study -q " + write("copy.toml", text + "[bogus]\nx = 1\n") + " -o out");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("unknown section [bogus]"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

TEST_F(StudyCli, MissingStudyFileIsAnError) {
  const Result r = run("study -q nosuch-study.toml -o out");
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.err.find("nosuch-study.toml"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

namespace {

// The /results numbers the tests compare between runs (NaN equals NaN).
std::vector<double> someResults(const fs::path& results) {
  const granwave::h5::File f = granwave::h5::File::openReadOnly(results.string());
  std::vector<double> v;
  for (const char* group : {"/results/wave_fronts/ed_dry", "/results/wave_fronts/ed_wet",
                            "/results/wave_fronts/hydro_dry_velocity"})
    for (const char* name : {"weak", "weak_error", "strong", "strong_error", "all"})
      v.push_back(f.readAttribute<double>(group, name));
  for (double x : f.readDataset<double>("/results/wave_fronts/n_sweep/dry/ed_speed"))
    v.push_back(x);
  return v;
}

void expectSameNumbers(const std::vector<double>& a, const std::vector<double>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::isnan(a[i]))
      EXPECT_TRUE(std::isnan(b[i])) << "number " << i;
    else
      EXPECT_EQ(a[i], b[i]) << "number " << i;
  }
}

// The label a run record names.
std::string labelOf(const fs::path& record) {
  std::ifstream in(record);
  std::string line;
  while (std::getline(in, line))
    if (line.starts_with("label = ")) return line.substr(9, line.size() - 10);  // '...'
  return "";
}

}  // namespace

TEST_F(StudyCli, TinyStudyWritesResultsAndReportThenRerunReusesEveryRunAndRedoesOnlyDeletedOne) {
  const std::string command = "study " + kTinyStudy + " -o out -j 2";
  const fs::path results = dir_ / "out" / "results.h5";

  // First run: everything is done.
  const Result first = run(command + " -q");
  if (binaryRebuilt()) GTEST_SKIP() << kRebuilt;
  ASSERT_EQ(first.code, 0) << first.err;
  EXPECT_EQ(first.err, "");  // -q: no progress lines
  EXPECT_NE(first.out.find("results.h5"), std::string::npos) << first.out;
  ASSERT_TRUE(fs::exists(results));
  EXPECT_TRUE(fs::exists(dir_ / "out" / "report.html"));
  {
    const granwave::h5::File f = granwave::h5::File::openReadOnly(results.string());
    EXPECT_EQ(f.readStringAttribute("/", "format"), "granwave-study-1");
    EXPECT_EQ(f.readStringAttribute("/", "study"), "wave-fronts");
    EXPECT_TRUE(f.isGroup("/results/wave_fronts"));
    EXPECT_TRUE(f.isGroup("/report"));
    const auto labels = f.readStringArrayAttribute("/runs", "label");
    EXPECT_EQ(labels.size(), f.readDataset<double>("/runs/wall_seconds").size());
    EXPECT_NE(std::find(labels.begin(), labels.end(), "ED dry N=150"), labels.end());
  }
  const std::vector<double> numbers = someResults(results);
  const std::vector<fs::path> done = records("out");
  ASSERT_GT(done.size(), 10u);
  for (const fs::path& d : done)  // every record, failed runs included, is a finished run
    EXPECT_EQ(slurp(d).find("interrupted"), std::string::npos) << d;

  // Second run of the same command: every run is reused, the results are the same.
  const Result second = run(command);
  if (binaryRebuilt()) GTEST_SKIP() << kRebuilt;
  ASSERT_EQ(second.code, 0) << second.err;
  const auto p2 = progress(second.err);
  ASSERT_TRUE(p2) << second.err;
  EXPECT_EQ(p2->runs, static_cast<int>(done.size()));
  EXPECT_EQ(p2->reused, p2->runs) << second.err;
  EXPECT_EQ(p2->to_do, 0) << second.err;
  EXPECT_EQ(second.err.find("] "), std::string::npos) << "a run was redone:\n" << second.err;
  expectSameNumbers(someResults(results), numbers);

  // Without one run's record only that run is redone, to the same results.
  const auto deleted = std::find_if(done.begin(), done.end(),
                                    [](const fs::path& d) { return labelOf(d) == "ED dry N=150"; });
  ASSERT_NE(deleted, done.end());
  const std::string text = slurp(*deleted);
  fs::remove(*deleted);
  const Result third = run(command);
  if (binaryRebuilt()) GTEST_SKIP() << kRebuilt;
  ASSERT_EQ(third.code, 0) << third.err;
  const auto p3 = progress(third.err);
  ASSERT_TRUE(p3) << third.err;
  EXPECT_EQ(p3->runs, p2->runs);
  EXPECT_EQ(p3->reused, p2->runs - 1) << third.err;
  EXPECT_EQ(p3->to_do, 1) << third.err;
  EXPECT_NE(third.err.find("[  1/1] ED dry N=150"), std::string::npos) << third.err;
  ASSERT_TRUE(fs::exists(*deleted));
  EXPECT_EQ(records("out"), done);
  EXPECT_NE(slurp(*deleted).find("ok = true"), std::string::npos) << slurp(*deleted);
  EXPECT_NE(text.find("ok = true"), std::string::npos) << text;
  expectSameNumbers(someResults(results), numbers);
}

namespace {

// Starts the binary with `args` in `dir`, stdout and stderr to files there.
pid_t spawn(const fs::path& dir, const std::vector<std::string>& args) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  const std::string out = (dir / "out.txt").string(), err = (dir / "err.txt").string();
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, out.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  // SIGINT as a terminal would deliver it, even if this test inherited it ignored.
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  sigset_t defaults;
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGINT);
  posix_spawnattr_setsigdefault(&attr, &defaults);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGDEF);
  std::vector<char*> argv;
  const std::string program = GRANWAVE_BINARY;
  argv.push_back(const_cast<char*>(program.c_str()));
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = -1;
  const int rc = posix_spawn(&pid, program.c_str(), &actions, &attr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attr);
  return rc == 0 ? pid : -1;
}

}  // namespace

TEST_F(StudyCli, InterruptExitsWith130KeepsFinishedRunsAndTheSameCommandResumes) {
  const fs::path out = dir_ / "out";
  const pid_t pid = spawn(dir_, {"study", kTinyStudy, "-o", out.string(), "-j", "2"});
  ASSERT_GT(pid, 0);
  // Interrupt once the study has announced its runs (its handler is in place by then), however
  // slowly it starts (a loaded machine, a sanitizer build).
  ASSERT_TRUE(waitForText(dir_ / "err.txt", "granwave study: ", std::chrono::seconds(120)))
      << slurp(dir_ / "err.txt");
  ASSERT_EQ(::kill(pid, SIGINT), 0);  // the study only: it stops its runs itself
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  if (binaryRebuilt()) GTEST_SKIP() << kRebuilt;
  const std::string err = slurp(dir_ / "err.txt");
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status) << "\n" << err;
  EXPECT_EQ(WEXITSTATUS(status), 130) << err;
  EXPECT_NE(err.find("granwave: interrupted: "), std::string::npos) << err;
  EXPECT_NE(err.find("run the same command again to resume"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(out / "results.h5"));
  EXPECT_FALSE(fs::exists(out / "report.html"));
  // Runs stopped by the interrupt are not results: nothing records them.
  const std::vector<fs::path> kept = records("out");
  for (const fs::path& d : kept)
    EXPECT_EQ(slurp(d).find("interrupted"), std::string::npos) << d << ":\n" << slurp(d);

  const Result resumed = run("study " + kTinyStudy + " -o out -j 2");
  if (binaryRebuilt()) GTEST_SKIP() << kRebuilt;
  ASSERT_EQ(resumed.code, 0) << resumed.err;
  const auto p = progress(resumed.err);
  ASSERT_TRUE(p) << resumed.err;
  EXPECT_EQ(p->reused, static_cast<int>(kept.size())) << resumed.err;
  EXPECT_EQ(p->reused + p->to_do, p->runs);
  EXPECT_GT(p->to_do, 0) << "the study finished before the interrupt; interrupt it sooner";
  EXPECT_TRUE(fs::exists(out / "results.h5"));
  EXPECT_TRUE(fs::exists(out / "report.html"));
  EXPECT_EQ(static_cast<int>(records("out").size()), p->runs);
}
