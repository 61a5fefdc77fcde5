#include "studies/runner/RunCache.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "files/OutputPath.hpp"
#include "scene/SceneDerived.hpp"
#include "scene/SceneParser.hpp"
#include "studies/runner/ChildProcess.hpp"

namespace granwave {

namespace {

std::uint64_t fnv1a(std::string_view bytes, std::uint64_t h = 1469598103934665603ull) {
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

}  // namespace

RunCache::RunCache(std::string directory, std::string build_id, ReadableCheck readable)
    : directory_(std::move(directory)),
      build_id_(std::move(build_id)),
      readable_(std::move(readable)) {
  std::filesystem::create_directories(directory_);
}

RunCache::RunCache(LookOnly, std::string directory, std::string build_id, ReadableCheck readable)
    : directory_(std::move(directory)),
      build_id_(std::move(build_id)),
      readable_(std::move(readable)) {}

RunCache RunCache::lookOnly(std::string directory, std::string build_id, ReadableCheck readable) {
  return RunCache(LookOnly{}, std::move(directory), std::move(build_id), std::move(readable));
}

// Outputs are renamed into place complete and the record follows them, so an output that
// exists but does not open was damaged afterwards (a disk error, a careless truncate).
bool RunCache::usable(const std::string& path) const {
  if (!std::filesystem::exists(path)) return false;
  if (!readable_ || readable_(path)) return true;
  fmt::print(stderr, "granwave study: {} cannot be read; making that run again\n", path);
  return false;
}

RunRecord RunCache::record(const RunRequest& given) const {
  RunRequest request = given;
  // A study reads a particle run's observables (every record), its fields and at most its last
  // frame, never the trajectory between: the run file keeps the first and the last frame only
  // (the paper's wet scene: 333 MB of trajectory otherwise). The stride is part of the scene
  // the run is made from, so of its key; `granwave simulate` of the run's scene file with
  // --set run.trajectory_stride=1 makes the whole trajectory (docs/studies.md).
  if (request.kind == RunKind::Particles)
    request.scene.run.trajectory_stride =
        static_cast<int>(std::max<std::uint64_t>(lastRecordStep(request.scene), 1));
  const char* kind = runKindName(request.kind);
  std::string key = std::string(kind) + "\n" + sceneToToml(request.scene);
  if (request.kind == RunKind::Lammps) {
    key += request.program + "\n" + request.deck_text;
    for (const std::string& v : request.variables) key += v + "\n";
  }
  if (request.kind == RunKind::Particles && request.fields)
    key += fmt::format("window={} blocks={}{}\n", request.window_cycles, request.blocks,
                       request.state_fields ? " states" : "");
  key += build_id_;
  RunRecord r;
  r.request = request;
  // Named by content alone, so two labels for the same scene share one run.
  r.stem = fmt::format("{}/{}-{:016x}", directory_, kind, fnv1a(key));
  return r;
}

bool RunCache::load(RunRecord& r) const {
  if (!std::filesystem::exists(r.recordPath())) return false;
  try {
    const toml::table t = toml::parse_file(r.recordPath());
    if (!t["ok"].is_boolean() || !t["exit_code"].is_integer()) return false;  // not a record
    r.ok = t["ok"].value_or(false);
    r.exit_code = static_cast<int>(t["exit_code"].value_or(std::int64_t{-1}));
    r.message = t["message"].value_or(std::string());
    r.wall = t["wall_seconds"].value_or(0.0);
    r.cpu = t["cpu_seconds"].value_or(0.0);
  } catch (const toml::parse_error&) {
    return false;  // unreadable record: run again
  }
  // A record whose outputs were removed since does not count: the run is made again.
  const bool hydro = r.request.kind == RunKind::Hydro;
  if (r.ok && r.request.kind == RunKind::Lammps) {
    if (!std::filesystem::exists(r.lammpsPath())) return false;
    r.reused = true;
    return true;
  }
  if (r.ok && !usable(hydro ? r.hydroPath() : r.runPath())) return false;
  if (r.ok && !hydro && r.request.fields && !usable(r.fieldsPath())) return false;
  r.reused = true;
  return true;
}

void RunCache::store(const RunRecord& r) const {
  toml::table t{{"label", r.request.label}, {"ok", r.ok},
                {"exit_code", r.exit_code}, {"message", r.message},
                {"wall_seconds", r.wall},   {"cpu_seconds", r.cpu}};
  // A temporary of this process beside the record (studies sharing the cache never share it),
  // renamed over the record: a reader sees the whole record or none.
  const std::string tmp = files::temporaryFor(r.recordPath());
  {
    std::ofstream out(tmp);
    out << t << "\n";
    if (!out) throw std::runtime_error(tmp + ": cannot write the run record");
  }
  std::filesystem::rename(tmp, r.recordPath());
}

std::string buildIdentity() {
  std::ifstream in(selfExecutable(), std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return fmt::format("{:016x}", fnv1a(bytes.str()));
}

}  // namespace granwave
