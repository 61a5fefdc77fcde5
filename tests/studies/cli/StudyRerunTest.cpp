// `granwave study` end to end on the tiny wave-fronts study (label `study`): results.h5 and
// report.html; the run cache (a rerun reuses every run and gives the same results; a run whose
// record is deleted is the only one redone); an interrupt (exit 130, finished runs kept, the
// same command resumes).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "h5/File.hpp"
#include "tests/studies/cli/StudyCliFixture.hpp"

extern char** environ;

namespace fs = std::filesystem;
using namespace granwave::testing;

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

// The rerun redid exactly the run labelled `label` and reused the others.
void expectOnlyRunRedone(const Result& r, int runs, const std::string& label) {
  ASSERT_EQ(r.code, 0) << r.err;
  const auto p = progress(r.err);
  ASSERT_TRUE(p) << r.err;
  EXPECT_EQ(p->runs, runs);
  EXPECT_EQ(p->reused, runs - 1) << r.err;
  EXPECT_EQ(p->to_do, 1) << r.err;
  EXPECT_NE(r.err.find("[  1/1] " + label), std::string::npos) << r.err;
}

}  // namespace

TEST_F(StudyCli,
       TinyStudyWritesResultsAndReportThenRerunReusesEveryRunAndRedoesOnlyDeletedOrDamagedOne) {
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
  expectOnlyRunRedone(third, p2->runs, "ED dry N=150");
  ASSERT_TRUE(fs::exists(*deleted));
  EXPECT_EQ(records("out"), done);
  EXPECT_NE(slurp(*deleted).find("ok = true"), std::string::npos) << slurp(*deleted);
  EXPECT_NE(text.find("ok = true"), std::string::npos) << text;
  expectSameNumbers(someResults(results), numbers);

  // A run file damaged after its record was written (cut in half) is made again, not read.
  const fs::path cut = fs::path(*deleted).replace_extension(".h5");
  fs::resize_file(cut, fs::file_size(cut) / 2);
  const Result fourth = run(command);
  if (binaryRebuilt()) GTEST_SKIP() << kRebuilt;
  expectOnlyRunRedone(fourth, p2->runs, "ED dry N=150");
  EXPECT_NE(fourth.err.find(cut.filename().string() + " cannot be read; making that run again"),
            std::string::npos)
      << fourth.err;
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
