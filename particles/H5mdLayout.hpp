#pragma once
// The on-disk contract of a granwave particle run (H5MD 1.1), shared by H5mdWriter and
// H5mdReader so the two cannot drift apart:
//
//   /h5md                      version = [1, 1]
//     author                   name
//     creator                  name = "granwave", version
//     modules/units            version = [1, 0], system = "SI"
//   /particles/all/box         dimension = 3, boundary = [x, "none", z] ("periodic"/"none")
//     edges/{step,time,value}  value [frames][3][3] = diag(width, thickness, height), m
//   /particles/all/{position,velocity,angular_velocity}/{step,time,value}
//                              value [frames][N][3]: (x, 0, z) m, (vx, 0, vz) m s-1,
//                              (0, omega, 0) rad s-1; every k-th record (step % k == 0)
//   /observables/<name>/{step,time,value}   every record; value [records], see below;
//                              collisions/value [records][4] with attribute "columns"
//   /parameters                completed (int64 1/0), summary (string, optional)
//     scene                    string dataset: the scene TOML as given
//     provenance               program_version, command_line, seed (uint64)
//   /granwave/pair_impacts     runs with phase-averaged fields only: the pair-impact
//                              normal-speed histogram over the fields' pooled cycles,
//                              counts [phase bins][speed bins] (PairImpactHistogram.hpp)
//
// step: int64 [n] (the snapshot's recording index); time: double [n], unit "s".
// Every value dataset has a string attribute "unit", in the H5MD units-module notation
// ("m s-1", not "m/s"; MDAnalysis accepts only that form for velocities).
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

#include "particles/Snapshot.hpp"

namespace granwave {

// The simulation box as H5MD sees it: the 2D layer is a slab one particle diameter thick.
struct BoxInfo {
  double width = 0;      // m, along x
  double height = 0;     // m, along z
  double thickness = 0;  // m, along y (the particle diameter)
  bool periodic_x = false;
  bool periodic_z = false;
};

// Where a run came from; stored in /parameters/provenance and /h5md.
struct RunProvenance {
  std::string program_version;
  std::string command_line;
  std::uint64_t seed = 0;
  std::string author;  // H5MD author/name; empty = $USER, else "unknown"
};

namespace h5md {

inline const std::string kBox = "/particles/all/box";
inline const std::string kEdges = "/particles/all/box/edges";
inline const std::string kPosition = "/particles/all/position";
inline const std::string kVelocity = "/particles/all/velocity";
inline const std::string kAngularVelocity = "/particles/all/angular_velocity";
inline const std::string kObservables = "/observables";
inline const std::string kParameters = "/parameters";
inline const std::string kScene = "/parameters/scene";
inline const std::string kProvenance = "/parameters/provenance";
inline const std::string kCreatorName = "granwave";
// Not an H5MD group (the format leaves the root open to a program's own data); outside
// /observables, whose every member MDAnalysis reads as a time series.
inline const std::string kPairImpacts = "/granwave/pair_impacts";

// Observables chunk: 1024 records (8 KiB of doubles), written a chunk at a time, shuffled and
// deflated (HDF5 filters every HDF5 reader decodes).
inline constexpr std::size_t kObservableChunk = 1024;

// A real-valued observable: /observables/<name>/value is double [records]. An observable
// added after files were written is `optional`: a file without it reads as NaN.
struct RealObservable {
  const char* name;
  const char* unit;
  double (*get)(const Snapshot&);
  void (*set)(Snapshot&, double);
  bool optional = false;
};

// A counter: /observables/<name>/value is uint64 [records], unit "1".
struct CountObservable {
  const char* name;
  std::uint64_t (*get)(const Snapshot&);
  void (*set)(Snapshot&, std::uint64_t);
};

// clang-format off
#define GRANWAVE_REAL(field, unit)                                   \
  RealObservable{#field, unit,                                       \
                 [](const Snapshot& s) { return s.obs.field; },      \
                 [](Snapshot& s, double v) { s.obs.field = v; }}
// clang-format on
inline constexpr std::array<RealObservable, 11> kRealObservables{
    GRANWAVE_REAL(center_of_mass_height, "m"),
    GRANWAVE_REAL(kinetic_energy, "J"),
    GRANWAVE_REAL(rotational_energy, "J"),
    GRANWAVE_REAL(potential_energy, "J"),
    GRANWAVE_REAL(dissipated_energy, "J"),
    GRANWAVE_REAL(wall_work, "J"),
    GRANWAVE_REAL(pressure, "Pa m"),
    GRANWAVE_REAL(pair_impact_energy, "J"),
    GRANWAVE_REAL(pair_impact_loss, "J"),
    RealObservable{"plate_height", "m", [](const Snapshot& s) { return s.plate_height; },
                   [](Snapshot& s, double v) { s.plate_height = v; }},
    RealObservable{"wall_dissipated_energy", "J",
                   [](const Snapshot& s) { return s.obs.wall_dissipated_energy; },
                   [](Snapshot& s, double v) { s.obs.wall_dissipated_energy = v; }, true},
};
#undef GRANWAVE_REAL

// clang-format off
#define GRANWAVE_COUNT(name, field)                                  \
  CountObservable{name,                                              \
                  [](const Snapshot& s) { return s.obs.field; },     \
                  [](Snapshot& s, std::uint64_t v) { s.obs.field = v; }}
// clang-format on
inline constexpr std::array<CountObservable, 1> kCountObservables{
    GRANWAVE_COUNT("events", events),
};

// Collision counts by kind: one table /observables/collisions/value, uint64 [records][4],
// unit "1", whose string-array attribute "columns" names the kinds in this order. A table
// rather than four groups /observables/collisions/<kind>/: MDAnalysis reads
// /observables/<name>/value for every <name> and fails on a nested group.
inline const std::string kCollisions = "/observables/collisions";
inline constexpr std::array<CountObservable, 4> kCollisionColumns{
    GRANWAVE_COUNT("pair", collisions.pair),
    GRANWAVE_COUNT("wall", collisions.wall),
    GRANWAVE_COUNT("tc_elastic", collisions.tc_elastic),
    GRANWAVE_COUNT("rests", collisions.rests),
};
#undef GRANWAVE_COUNT

inline std::string observableGroup(const std::string& name) { return kObservables + "/" + name; }

}  // namespace h5md
}  // namespace granwave
