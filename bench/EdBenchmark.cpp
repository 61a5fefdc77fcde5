// Benchmarks of the event-driven engine (docs/performance.md).
//
//  BM_ElasticGas/N/phi_permille  elastic hard-disk gas in a periodic square box, no gravity,
//                                no drive, e = 1, TC off, no friction. Timed: a fixed number
//                                of pair collisions after equilibration (20 collisions per
//                                particle). Rates are per CPU second: these benchmarks do not
//                                call UseRealTime(), so Google Benchmark divides kIsRate
//                                counters by the thread's CPU time.
//  BM_PaperScene/dry|wet         the paper's scene (N = 300, f = 10 Hz, Gamma = 4), the whole
//                                15 s run() as `granwave simulate` does it, without writing.
//                                These call UseRealTime(): their kIsRate counters are per
//                                wall second (the target is "15 simulated seconds in under 5
//                                wall seconds"). CPU-second figures are reported explicitly.
//
// Memory: before each benchmark's setup the process's peak RSS is reset (Linux,
// /proc/self/clear_refs = 5); peak_RSS_MiB is VmHWM after the run (it includes the process's
// baseline, base_RSS_MiB), B_per_particle = (VmHWM - baseline) / N.
// Everything is seeded (scene.run.seed = 1): runs are reproducible event for event.
#include <benchmark/benchmark.h>
#include <malloc.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <fstream>
#include <memory>
#include <numbers>
#include <string>

#include "particles/EdSimulation.hpp"
#include "particles/InelasticCollapse.hpp"
#include "particles/InitialState.hpp"
#include "scene/Scene.hpp"

namespace {

using granwave::EdSimulation;
using granwave::EngineConfig;
using granwave::InitialCondition;
using granwave::Scene;

double threadCpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

double wallSeconds() {
  using clock = std::chrono::steady_clock;
  return std::chrono::duration<double>(clock::now().time_since_epoch()).count();
}

// A "VmXXX:   1234 kB" line of /proc/self/status, in bytes (0 if absent).
double procStatusBytes(const char* key) {
  std::ifstream in("/proc/self/status");
  std::string line;
  const std::size_t n = std::strlen(key);
  while (std::getline(in, line)) {
    if (line.compare(0, n, key) == 0 && line.size() > n && line[n] == ':')
      return 1024.0 * std::stod(line.substr(n + 1));
  }
  return 0.0;
}

// Returns freed heap memory to the system, then resets the peak RSS (VmHWM) to the current
// RSS, so that VmHWM afterwards is this benchmark's own peak.
void resetPeakRss() {
  malloc_trim(0);
  std::ofstream out("/proc/self/clear_refs");
  out << "5";
}

constexpr double kMiB = 1024.0 * 1024.0;

// ---------------------------------------------------------------------------------------
// Elastic hard-disk gas

struct GasSetup {
  std::unique_ptr<EdSimulation> sim;
  double pair_rate = 0;  // pair collisions per simulated second, measured while equilibrating
};

// Box side L with N pi d^2 / 4 / L^2 = phi.
double boxSide(int n, double phi, double d) {
  return std::sqrt(n * std::numbers::pi * d * d / 4.0 / phi);
}

// Advances until `target` more pair collisions have happened; returns the measured rate
// (pair collisions per simulated second) over the second half.
double advanceCollisions(EdSimulation& sim, std::uint64_t target, double dt_guess) {
  const std::uint64_t start = sim.counters().collisions.pair;
  const std::uint64_t half = start + target / 2, end = start + target;
  double dt = dt_guess, rate = 0, t_half = -1;
  std::uint64_t c_half = 0;
  while (sim.counters().collisions.pair < end) {
    const std::uint64_t before = sim.counters().collisions.pair;
    sim.advanceTo(sim.now() + dt);
    const std::uint64_t c = sim.counters().collisions.pair;
    if (t_half < 0 && c >= half) {
      t_half = sim.now();
      c_half = c;
    }
    const std::uint64_t done = c - before;
    const std::uint64_t left = c < end ? end - c : 0;
    // Next slice: aim at a quarter of what is left (at least 1000 collisions), changing dt
    // by at most 4x per slice.
    const double aim = std::max(0.25 * static_cast<double>(left), 1000.0);
    const double wanted = done > 0 ? dt * aim / static_cast<double>(done) : 4.0 * dt;
    dt = std::clamp(wanted, 0.25 * dt, 4.0 * dt);
  }
  if (t_half >= 0 && sim.now() > t_half)
    rate = static_cast<double>(sim.counters().collisions.pair - c_half) / (sim.now() - t_half);
  return rate;
}

GasSetup makeGas(int n, double phi) {
  Scene s;
  s.particles.count = n;
  const double d = s.particles.diameter;
  const double L = boxSide(n, phi, d);
  s.container.width = L;
  s.container.height = L;
  s.container.periodic_x = true;
  s.container.periodic_z = true;
  s.drive.frequency = 0.0;
  s.drive.gamma.reset();
  s.contact.restitution = granwave::RestitutionKind::Constant;
  s.contact.e = 1.0;
  s.contact.friction = 0.0;
  s.contact.tc_enabled = false;
  s.run.gravity = 0.0;
  s.run.seed = 1;
  s.initial.temperature = 1e-6;  // J; rates per collision do not depend on it
  // Random sequential addition jams near 0.547 in 2D; denser states start on a lattice.
  s.initial.placement =
      phi < 0.45 ? granwave::InitialPlacement::Random : granwave::InitialPlacement::Lattice;

  EngineConfig cfg = granwave::engineConfig(s);
  cfg.restitution = granwave::Restitution::constant(1.0);
  cfg.tc = 0;
  cfg.gravity = 0;
  cfg.plate = {};
  cfg.periodic_x = cfg.periodic_z = true;

  GasSetup g;
  {
    const InitialCondition ic = granwave::initialCondition(s, cfg);
    g.sim = std::make_unique<EdSimulation>(cfg, ic);
  }
  // Equilibrate: 20 collisions per particle (10 N pair collisions).
  const double v = std::sqrt(*s.initial.temperature / cfg.mass);
  g.pair_rate = advanceCollisions(*g.sim, 10ULL * n, 0.01 * d / v);
  return g;
}

void BM_ElasticGas(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const double phi = static_cast<double>(state.range(1)) / 1000.0;
  // Timed collisions per iteration: a few seconds at the target rate.
  const std::uint64_t timed = static_cast<std::uint64_t>(state.range(2));

  resetPeakRss();
  const double base_rss = procStatusBytes("VmRSS");
  GasSetup g;
  try {
    g = makeGas(n, phi);
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  EdSimulation& sim = *g.sim;

  std::uint64_t pairs = 0, events = 0;
  double cpu = 0, wall = 0, sim_time = 0;
  for (auto _ : state) {
    const std::uint64_t p0 = sim.counters().collisions.pair, e0 = sim.counters().events;
    const double t0 = sim.now(), c0 = threadCpuSeconds(), w0 = wallSeconds();
    // One advanceTo spanning the expected time of `timed` collisions, then small top-ups.
    sim.advanceTo(sim.now() + 0.98 * static_cast<double>(timed) / g.pair_rate);
    while (sim.counters().collisions.pair - p0 < timed)
      sim.advanceTo(sim.now() + 0.01 * static_cast<double>(timed) / g.pair_rate);
    cpu += threadCpuSeconds() - c0;
    wall += wallSeconds() - w0;
    pairs += sim.counters().collisions.pair - p0;
    events += sim.counters().events - e0;
    sim_time += sim.now() - t0;
  }
  const double peak = procStatusBytes("VmHWM");
  const double live = procStatusBytes("VmRSS");

  using benchmark::Counter;
  // Divided by the benchmark's CPU time (no UseRealTime() on this benchmark).
  state.counters["coll/cpu_s"] = Counter(static_cast<double>(pairs), Counter::kIsRate);
  state.counters["events/cpu_s"] = Counter(static_cast<double>(events), Counter::kIsRate);
  // Explicit cross-checks from our own clocks.
  state.counters["ns/coll_cpu"] = 1e9 * cpu / static_cast<double>(pairs);
  state.counters["coll/wall_s"] = static_cast<double>(pairs) / wall;
  state.counters["events/coll"] = static_cast<double>(events) / static_cast<double>(pairs);
  state.counters["coll/particle"] = 2.0 * static_cast<double>(pairs) / n;
  state.counters["peak_RSS_MiB"] = peak / kMiB;
  state.counters["base_RSS_MiB"] = base_rss / kMiB;
  state.counters["B/particle_peak"] = (peak - base_rss) / n;
  state.counters["B/particle_live"] = (live - base_rss) / n;
  state.SetLabel(phi < 0.45 ? "random placement" : "lattice placement");
}

// {N, area fraction x 1000, timed pair collisions}
BENCHMARK(BM_ElasticGas)
    ->ArgNames({"N", "phi_permille", "timed_coll"})
    ->Args({10'000, 300, 4'000'000})
    ->Args({10'000, 500, 4'000'000})
    ->Args({10'000, 600, 4'000'000})
    ->Args({100'000, 300, 4'000'000})
    ->Args({100'000, 500, 4'000'000})
    ->Args({100'000, 600, 4'000'000})
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

// ---------------------------------------------------------------------------------------
// The paper's scene

void BM_PaperScene(benchmark::State& state) {
  const bool wet = state.range(0) != 0;
  Scene s;  // defaults = the paper's scene: N = 300, f = 10 Hz, Gamma = 4, 15 s, dry law
  if (wet) s.contact.restitution = granwave::RestitutionKind::Wet;
  s.run.seed = 1;

  resetPeakRss();
  const double base_rss = procStatusBytes("VmRSS");
  std::unique_ptr<EdSimulation> sim;
  try {
    const EngineConfig cfg = granwave::engineConfig(s);
    const InitialCondition ic = granwave::initialCondition(s, cfg);
    sim = std::make_unique<EdSimulation>(cfg, ic);
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }

  double cpu = 0, wall = 0, sim_time = 0;
  std::string failure;
  for (auto _ : state) {
    const double c0 = threadCpuSeconds(), w0 = wallSeconds(), t0 = sim->now();
    try {
      sim->run();  // records every T/100 (no observers attached), like `granwave simulate`
    } catch (const granwave::InelasticCollapse& e) {
      // The engine stops at a detected collapse; the rates up to there are still measured
      // (the collapse itself is 2000 collisions of one particle, a negligible share).
      failure = e.what();
    } catch (const std::exception& e) {
      state.SkipWithError(e.what());
      break;
    }
    cpu += threadCpuSeconds() - c0;
    wall += wallSeconds() - w0;
    sim_time += sim->now() - t0;
  }
  if (sim_time <= 0) return;
  const auto& obs = sim->counters();
  const double events = static_cast<double>(obs.events);

  using benchmark::Counter;
  // Divided by the benchmark's real (wall) time: this benchmark calls UseRealTime().
  state.counters["events/wall_s"] = Counter(events, Counter::kIsRate);
  state.counters["sim_s/wall_s"] = Counter(sim_time, Counter::kIsRate);
  // Explicit, from our own clocks.
  state.counters["events/cpu_s"] = events / cpu;
  state.counters["cpu_s/sim_s"] = cpu / sim_time;
  state.counters["wall_s_15s"] = wall / sim_time * 15.0;
  state.counters["pair/sim_s"] = static_cast<double>(obs.collisions.pair) / sim_time;
  state.counters["wall/sim_s"] = static_cast<double>(obs.collisions.wall) / sim_time;
  state.counters["events/coll"] =
      events / static_cast<double>(obs.collisions.pair + obs.collisions.wall);
  state.counters["peak_RSS_MiB"] = procStatusBytes("VmHWM") / kMiB;
  state.counters["base_RSS_MiB"] = base_rss / kMiB;
  char label[64];
  std::snprintf(label, sizeof label, "%s law, reached t = %.3f s%s", wet ? "wet" : "dry",
                sim->now(), failure.empty() ? "" : " (INELASTIC COLLAPSE)");
  state.SetLabel(label);
  if (!failure.empty())
    std::fprintf(stderr, "BM_PaperScene/wet:%d: %s\n", wet ? 1 : 0, failure.c_str());
}

BENCHMARK(BM_PaperScene)
    ->ArgNames({"wet"})
    ->Arg(0)
    ->Arg(1)
    ->Iterations(1)
    ->UseRealTime()
    ->Unit(benchmark::kSecond);

}  // namespace

int main(int argc, char** argv) {
  // A fixed mmap threshold: large arrays (everything O(N)) are mmapped and given back to the
  // system when freed, so that one benchmark's memory does not hide in the next one's RSS.
  mallopt(M_MMAP_THRESHOLD, 64 * 1024);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
