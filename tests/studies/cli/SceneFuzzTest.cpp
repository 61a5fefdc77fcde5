// A seeded mutational fuzzer over the paper's scenes (scenes/paper-dry.toml, paper-wet.toml):
// each mutant changes one or two keys to a value drawn from boundary and extreme numbers
// (0, negative, subnormal, huge, the old value times 10^k) and runs `granwave simulate` for a
// short time under a wall-clock limit. Whatever the mutant, the command must not crash, must
// not hang past the limit, must fail (if it fails) with one line and a documented exit code,
// and a run that exits 0 must hold only finite numbers and no overlapping particles.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "AddressSanitizer.hpp"
#include "particles/H5mdReader.hpp"
#include "scene/SceneParser.hpp"

namespace fs = std::filesystem;

namespace {

constexpr int kShards = 10;
constexpr int kMutantsPerShard = 20;
// A 0.02 s run takes a few seconds even when crawling; the sanitizer build runs the same code
// several times slower, on a shared machine, so its limit is wider.
#if GRANWAVE_ADDRESS_SANITIZER
constexpr int kWallLimitSeconds = 300;
#else
constexpr int kWallLimitSeconds = 60;
#endif

struct Key {
  const char* name;
  double paper;  // the paper's value, the base of multiplicative mutations
  bool integer;
};

const Key kKeys[] = {
    {"particles.count", 300, true},
    {"particles.diameter", 0.002, false},
    {"particles.density", 2580, false},
    {"particles.youngs_modulus", 63e9, false},
    {"container.width", 0.06, false},
    {"container.height", 0.06, false},
    {"drive.frequency", 10, false},
    {"drive.gamma", 4, false},
    {"contact.e_inf", 0.91, false},
    {"contact.kappa", 0.1, false},
    {"contact.viscosity", 1e-3, false},
    {"contact.friction", 0.5, false},
    {"contact.rest_velocity", 1e-6, false},
    {"contact.stokes_critical", 40, false},
    {"contact.tc", 1e-5, false},
    {"initial.temperature", 1e-7, false},
    {"run.gravity", 9.81, false},
    {"run.phases_per_cycle", 100, true},
};

std::string mutantValue(const Key& k, std::mt19937_64& rng) {
  const double specials[] = {0.0, -1.0, 5e-324, 1e-300, 1e300, 1e6, 2147483647.0};
  std::uniform_int_distribution<int> pick(0, 2);
  double v;
  if (pick(rng) == 0) {
    v = specials[std::uniform_int_distribution<int>(0, 6)(rng)];
  } else {
    v = k.paper * std::pow(10.0, std::uniform_int_distribution<int>(-8, 8)(rng));
  }
  std::ostringstream os;
  if (k.integer && std::abs(v) < 9e18) {
    os << static_cast<long long>(v);
  } else {
    os.precision(17);
    os << v;
    if (os.str().find_first_of(".e") == std::string::npos) os << ".0";
  }
  return os.str();
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The first pair of particles closer than d (1e-6 d of round-off), or {-1, -1}: a sweep along x
// over the particles sorted by x (with images of those near x = 0 for a periodic x).
std::pair<int, int> firstOverlap(const granwave::Snapshot& s, const granwave::Scene& scene) {
  const double d = scene.particles.diameter, min2 = d * d * (1.0 - 2e-6);
  struct Point {
    double x, z;
    int id;
  };
  std::vector<Point> p;
  for (int i = 0; i < s.size(); ++i) {
    p.push_back({s.x[i], s.z[i], i});
    if (scene.container.periodic_x && s.x[i] < d)
      p.push_back({s.x[i] + scene.container.width, s.z[i], i});
  }
  std::sort(p.begin(), p.end(), [](const Point& a, const Point& b) { return a.x < b.x; });
  for (std::size_t a = 0; a < p.size(); ++a) {
    for (std::size_t b = a + 1; b < p.size() && p[b].x - p[a].x < d; ++b) {
      const double dx = p[b].x - p[a].x, dz = p[b].z - p[a].z;
      if (p[a].id != p[b].id && dx * dx + dz * dz < min2) return {p[a].id, p[b].id};
    }
  }
  return {-1, -1};
}

// Finite numbers everywhere and no overlapping particles in any frame.
void expectSoundRun(const fs::path& file, const std::string& what) {
  granwave::H5mdReader reader(file.string());
  const granwave::Scene scene = granwave::parseSceneString(reader.sceneToml());
  // At most about 500 frames, evenly spaced, and always the last (a NaN, once there, stays):
  // reading 10^4 frames one by one would cost minutes.
  const std::size_t frames = reader.frameCount();
  const std::size_t stride = std::max<std::size_t>(1, frames / 500);
  for (std::size_t f = 0; f < frames;
       f = (f + stride < frames || f + 1 == frames) ? f + stride : frames - 1) {
    const granwave::Snapshot s = reader.frame(f);
    for (int i = 0; i < s.size(); ++i) {
      ASSERT_TRUE(std::isfinite(s.x[i]) && std::isfinite(s.z[i]) && std::isfinite(s.vx[i]) &&
                  std::isfinite(s.vz[i]))
          << what << ": particle " << i << " at frame " << f;
    }
    const auto [i, j] = firstOverlap(s, scene);
    ASSERT_EQ(i, -1) << what << ": particles " << i << ", " << j << " overlap at frame " << f;
  }
}

class SceneFuzz : public ::testing::TestWithParam<int> {};

TEST_P(SceneFuzz, MutantsNeverCrashHangOrExitZeroWithNaNOrOverlaps) {
  const int shard = GetParam();
  std::mt19937_64 rng(0x5eed0000u + static_cast<std::uint64_t>(shard));
  const fs::path dir = fs::temp_directory_path() / ("granwave_fuzz_" + std::to_string(::getpid()) +
                                                    "_" + std::to_string(shard));
  fs::remove_all(dir);
  fs::create_directories(dir);
  int outcomes[4] = {0, 0, 0, 0};  // exit 0 (checked), 1, 2 (refused), 3 (engine breakdown)
  for (int m = 0; m < kMutantsPerShard; ++m) {
    const char* base = rng() % 2 ? "paper-dry" : "paper-wet";
    std::string sets = " --set run.duration=0.02";
    const int keys = 1 + static_cast<int>(rng() % 2);
    for (int k = 0; k < keys; ++k) {
      const Key& key = kKeys[rng() % std::size(kKeys)];
      sets += std::string(" --set ") + key.name + "=" + mutantValue(key, rng);
    }
    const std::string what = std::string(base) + sets;
    fs::remove(dir / "run.h5");
    const std::string cmd = "cd '" + dir.string() + "' && timeout -s KILL " +
                            std::to_string(kWallLimitSeconds) +
                            " '" GRANWAVE_BINARY "' simulate -q '" GRANWAVE_SOURCE_DIR "/scenes/" +
                            base + ".toml'" + sets + " -o run.h5 > out.txt 2> err.txt";
    const auto start = std::chrono::steady_clock::now();
    const int status = std::system(cmd.c_str());
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (seconds > 5) std::printf("slow mutant (%.1f s): %s\n", seconds, what.c_str());
    ASSERT_TRUE(WIFEXITED(status)) << what << ": killed by a signal";
    const int code = WEXITSTATUS(status);
    ASSERT_NE(code, 137) << what << ": still running after " << kWallLimitSeconds << " s";
    const std::string err = slurp(dir / "err.txt");
    if (code >= 0 && code <= 3) ++outcomes[code];
    if (code != 0) {
      EXPECT_TRUE(code == 1 || code == 2 || code == 3) << what << ": exit " << code << ": " << err;
      EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << what << ": " << err;
      EXPECT_FALSE(fs::exists(dir / "run.h5")) << what;
      continue;
    }
    expectSoundRun(dir / "run.h5", what);
  }
  std::printf("shard %d: %d ran and were checked, %d refused, %d engine breakdowns, %d other\n",
              shard, outcomes[0], outcomes[2], outcomes[3], outcomes[1]);
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Seeded, SceneFuzz, ::testing::Range(0, kShards));

}  // namespace
