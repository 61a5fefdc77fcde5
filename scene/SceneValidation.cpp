// Semantic checks of a complete scene (after file and overrides): ranges of single keys first,
// then geometry (the container must hold a particle and the particles), drive and packing.
// Each failure names the key, its value and origin, and what is valid (docs/scenes.md).
#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <tuple>

#include "scene/PlacementCapacity.hpp"
#include "scene/SceneDerived.hpp"
#include "scene/SceneDetail.hpp"
#include "scene/SceneParser.hpp"

namespace granwave {
namespace detail {

std::string SceneOrigins::describe(std::string_view key, std::string_view value) const {
  const auto it = where.find(key);
  if (it == where.end())
    return fmt::format("{}: {} = {}{}", file, key, value, parsed ? " (default)" : "");
  return fmt::format("{}: {} = {}", it->second, key, value);
}

namespace {

constexpr long long kMaxParticles = 1'000'000;
constexpr double kMaxRecords = 1e6;
constexpr double kMaxStoredFrames = 2.5e8;
// The cell grid has about (width / d) x (height / d) cells of 4 bytes.
constexpr double kMaxCells = 1e7;

class Checker {
 public:
  Checker(const Scene& s, const SceneOrigins& o) : s_(s), o_(o) {}

  [[noreturn]] void fail(std::string_view key, std::string_view value,
                         std::string_view problem) const {
    throw SceneError(fmt::format("{}: {}", o_.describe(key, value), problem));
  }
  void fail(std::string_view key, double value, std::string_view problem) const {
    fail(key, tomlNumber(value), problem);
  }
  void positive(std::string_view key, double v, std::string_view unit) const {
    if (!(v > 0 && std::isfinite(v))) fail(key, v, fmt::format("must be > 0 ({})", unit));
  }
  void nonNegative(std::string_view key, double v, std::string_view unit) const {
    if (!(v >= 0 && std::isfinite(v))) fail(key, v, fmt::format("must be >= 0 ({})", unit));
  }
  // Interval with open/closed ends given as "(", "[", ")", "]".
  void within(std::string_view key, double v, char open, double lo, double hi, char close,
              std::string_view unit = "") const {
    const bool okLo = open == '[' ? v >= lo : v > lo;
    const bool okHi = close == ']' ? v <= hi : v < hi;
    if (!(okLo && okHi)) {
      fail(key, v,
           fmt::format("must be in {}{}, {}{}{}", open, tomlNumber(lo), tomlNumber(hi), close,
                       unit.empty() ? "" : fmt::format(" ({})", unit)));
    }
  }
  // 0 (the quantity switched off) or a value in [lo, hi].
  void zeroOrWithin(std::string_view key, double v, double lo, double hi,
                    std::string_view unit) const {
    if (!(v == 0 || (v >= lo && v <= hi))) {
      fail(key, v,
           fmt::format("must be 0 or in [{}, {}] ({})", tomlNumber(lo), tomlNumber(hi), unit));
    }
  }
  void atLeast(std::string_view key, long long v, long long min) const {
    if (v < min) fail(key, std::to_string(v), fmt::format("must be an integer >= {}", min));
  }
  void atMost(std::string_view key, long long v, long long max, std::string_view why) const {
    if (v > max)
      fail(key, std::to_string(v), fmt::format("must be an integer <= {} ({})", max, why));
  }

  void singleKeys() const;
  void temperature() const;
  void records() const;
  void drive() const;
  void geometry() const;
  void fallingBox() const;
  void placement() const;

 private:
  const Scene& s_;
  const SceneOrigins& o_;
};

// Ranges (docs/scenes.md, "Why these ranges"): wide enough for any granular experiment, narrow
// enough that every derived quantity (m, A, t_c, q, v_c, fall time sqrt(d/g)) is a normal
// double far from under- and overflow, so that the engine's tolerances (relative to d) hold.
void Checker::singleKeys() const {
  const auto& p = s_.particles;
  const auto& c = s_.contact;
  atLeast("particles.count", p.count, 1);
  atMost("particles.count", p.count, kMaxParticles, "the state of 10^6 particles fits in memory");
  within("particles.diameter", p.diameter, '[', 1e-6, 1.0, ']', "m");
  within("particles.density", p.density, '[', 10.0, 1e5, ']', "kg/m^3");
  within("particles.youngs_modulus", p.youngs_modulus, '[', 1e3, 1e13, ']', "Pa");
  within("particles.poisson_ratio", p.poisson_ratio, '(', -1.0, 0.5, ')');
  positive("container.width", s_.container.width, "m");
  positive("container.height", s_.container.height, "m");
  zeroOrWithin("drive.frequency", s_.drive.frequency, 1e-2, 1e4, "Hz; 0 = no drive");
  if (s_.drive.gamma) zeroOrWithin("drive.gamma", *s_.drive.gamma, 1e-3, 100.0, "g");
  if (s_.drive.amplitude) nonNegative("drive.amplitude", *s_.drive.amplitude, "m");
  within("contact.e", c.e, '[', 0.0, 1.0, ']');
  within("contact.kappa", c.kappa, '[', 0.0, 10.0, ']', "in the unit of contact.kappa_units");
  if (c.kappa_units == KappaUnits::GravityDiameter && !(s_.run.gravity > 0))
    fail("contact.kappa_units", "\"gd\"",
         "the unit sqrt(g d) needs run.gravity > 0; use \"si\" or \"cgs\"");
  within("contact.e_inf", c.e_inf, '(', 0.0, 1.0, ']');
  within("contact.stokes_critical", c.stokes_critical, '[', 0.0, 1e6, ']');
  within("contact.viscosity", c.viscosity, '[', 1e-6, 1e3, ']', "Pa s");
  within("contact.friction", c.friction, '[', 0.0, 10.0, ']', "0 = no rotation");
  within("contact.tangential_limit", c.tangential_limit, '[', -1.0, 1.0, ']');
  if (c.tc_enabled && c.tc_time && !(*c.tc_time >= 1e-12 && *c.tc_time <= 1.0)) {
    fail("contact.tc", *c.tc_time, R"(must be "auto", "off" or a time in seconds in [1e-12, 1.0])");
  }
  within("contact.rest_velocity", c.rest_velocity, '[', 0.0, 1e-2, ']', "m/s");
  within("run.duration", s_.run.duration, '(', 0.0, 1e5, ']', "s");
  atLeast("run.phases_per_cycle", s_.run.phases_per_cycle, 1);
  atMost("run.phases_per_cycle", s_.run.phases_per_cycle, 10000, "recordings per drive cycle");
  nonNegative("run.record_interval", s_.run.record_interval, "s; 0 = duration / 100");
  atLeast("run.trajectory_stride", s_.run.trajectory_stride, 1);
  if (s_.run.seed > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
    fail("run.seed", std::to_string(s_.run.seed), "must be an integer in [0, 2^63 - 1]");
  zeroOrWithin("run.gravity", s_.run.gravity, 1e-3, 1e4, "m/s^2, magnitude");
  atLeast("hydro.dimensions", s_.hydro.dimensions, 1);
  atMost("hydro.dimensions", s_.hydro.dimensions, 2, "1: the averaged layer, 2: the x-z plane");
  atLeast("hydro.columns", s_.hydro.columns, 0);
  atMost("hydro.columns", s_.hydro.columns, 10000, "columns across the width; 0 = one per 4 d");
  if (s_.hydro.dimensions == 2 && s_.hydro.walls == HydroWalls::Hard)
    fail("hydro.walls", "\"hard\"",
         "is built for the 1D layer (hydro.dimensions = 1); the 2D layer has \"spring\" walls");
  within("hydro.perturbation", s_.hydro.perturbation, '[', 0.0, 0.1, ']',
         "RMS of the columns' relative masses");
  within("hydro.remap_share", s_.hydro.remap_share, '[', 0.0, 0.9, ']',
         "a cell's share of its layer's mass that triggers the 2D remap; 0 = never");
  atLeast("hydro.cells", s_.hydro.cells, 8);
  atMost("hydro.cells", s_.hydro.cells, 100000, "cells across the height");
  within("hydro.rtol", s_.hydro.rtol, '[', 1e-12, 0.1, ']', "relative tolerance");
  within("hydro.atol", s_.hydro.atol, '[', 1e-16, 1e-2, ']', "absolute tolerance");
  within("hydro.contact_pressure", s_.hydro.contact_pressure, '[', 0.0, 1e6, ']');
  within("hydro.initial_temperature", s_.hydro.initial_temperature, '(', 0.0, 100.0, ']', "T0");
  within("hydro.artificial_viscosity", s_.hydro.artificial_viscosity, '[', 0.0, 10.0, ']');
  within("hydro.wall_contact_range", s_.hydro.wall_contact_range, '(', 0.0, 0.5, ']', "diameters");
  within("hydro.wall_contact_stiffness", s_.hydro.wall_contact_stiffness, '(', 0.0,
         s_.hydro.wall_contact_range, ')', "diameters, below hydro.wall_contact_range");
  within("hydro.packing_width", s_.hydro.packing_width, '[', 1e-8, 1e-2, ']',
         "of the close-packed density");
  within("hydro.temperature_floor", s_.hydro.temperature_floor, '[', 1e-60, 1e-10, ']', "g sigma");
}

// The initial temperature as a thermal speed sqrt(2 T / m): hard spheres at more than 1 km/s
// are outside every contact law here, and below 1e-9 m/s the squared speeds that predict
// collisions underflow.
void Checker::temperature() const {
  if (!s_.initial.temperature) return;
  const double T = *s_.initial.temperature;
  nonNegative("initial.temperature", T, "J per particle");
  const double m = derive(s_).mass;
  const double speed = std::sqrt(2.0 * T / m);
  if (T > 0 && !(speed >= 1e-9 && speed <= 1e3)) {
    fail("initial.temperature", T,
         fmt::format("gives a thermal speed sqrt(2 T / m) = {:.3g} m/s; it must be 0 or give a "
                     "speed in [1e-9, 1e3] m/s, T in [{:.3g}, {:.3g}] J for m = {:.3g} kg",
                     speed, 0.5 * m * 1e-18, 0.5 * m * 1e6, m));
  }
}

// The number of records must fit in memory and on disk: at most 10^6 records and at most
// 2.5e8 stored particle frames (40 bytes each, 10 GB).
void Checker::records() const {
  const auto& r = s_.run;
  const bool driven = s_.drive.frequency > 0;
  const double interval = driven ? 1.0 / (r.phases_per_cycle * s_.drive.frequency)
                                 : (r.record_interval > 0 ? r.record_interval : r.duration / 100);
  const double records = r.duration / interval;
  const char* key = driven ? "run.duration" : "run.record_interval";
  const double value = driven ? r.duration : r.record_interval;
  if (records > kMaxRecords) {
    fail(key, value,
         fmt::format("makes {:.4g} records (duration x frequency x phases_per_cycle, or duration "
                     "/ record_interval); at most 1e6 fit",
                     records));
  }
  const double frames = records / r.trajectory_stride * s_.particles.count;
  if (frames > kMaxStoredFrames) {
    fail("run.trajectory_stride", std::to_string(r.trajectory_stride),
         fmt::format("{:.4g} particle positions would be stored (records / stride x count); at "
                     "most 2.5e8 (10 GB): raise the stride",
                     frames));
  }
}

void Checker::drive() const {
  const auto& d = s_.drive;
  if (d.frequency <= 0) return;
  if (d.gamma && d.amplitude) {
    fail("drive.amplitude", *d.amplitude,
         fmt::format("give drive.gamma (= {}) or drive.amplitude, not both", tomlNumber(*d.gamma)));
  }
  if (!d.gamma && !d.amplitude)
    fail("drive.gamma", "none", "a driven scene needs gamma or amplitude");
  if (d.gamma && *d.gamma > 0 && s_.run.gravity == 0) {
    fail("drive.gamma", *d.gamma,
         "with run.gravity = 0 the amplitude Gamma g / (2 pi f)^2 is 0; give drive.amplitude");
  }
  if (s_.container.periodic_z) {
    fail("container.periodic_z", "true",
         fmt::format("a periodic z has no plate to drive; set drive.frequency = 0 (it is {})",
                     tomlNumber(d.frequency)));
  }
  const double A = derive(s_).amplitude;
  const double room = s_.container.height - s_.particles.diameter;
  if (2 * A >= room) {
    const char* key = d.amplitude ? "drive.amplitude" : "drive.gamma";
    fail(key, d.amplitude ? *d.amplitude : *d.gamma,
         fmt::format("impossible geometry: plate amplitude A = {:.4g} m, but 2A must be below "
                     "container.height - particles.diameter = {:.4g} m",
                     A, room));
  }
}

void Checker::geometry() const {
  const double d = s_.particles.diameter;
  const auto& box = s_.container;
  for (auto [key, length, periodic] :
       {std::tuple{"container.width", box.width, box.periodic_x},
        std::tuple{"container.height", box.height, box.periodic_z}}) {
    if (length < d) {
      fail(key, length, fmt::format("smaller than one particle diameter ({} m)", tomlNumber(d)));
    }
    // A box one particle across pins a particle between two walls at once: at length = d both
    // gaps are zero and the wall collisions form a cycle at one instant (docs/scenes.md).
    if (!periodic && length < 2 * d) {
      fail(key, length,
           fmt::format("a length between walls must be at least 2 particle diameters ({} m); a "
                       "column one particle wide is not supported",
                       tomlNumber(2 * d)));
    }
    if (periodic && length < 3 * d) {
      fail(key, length,
           fmt::format("a periodic length must be at least 3 particle diameters ({} m): the "
                       "engine's 3 x 3 cell stencil needs 3 cells of side >= d",
                       tomlNumber(3 * d)));
    }
  }
  if (std::floor(box.width / d) * std::floor(box.height / d) > kMaxCells) {
    fail("container.width", box.width,
         fmt::format("with container.height = {} m the box holds {:.3g} cells of one diameter; at "
                     "most 1e7 fit the engine's cell grid",
                     tomlNumber(box.height),
                     std::floor(box.width / d) * std::floor(box.height / d)));
  }
}

// What the initial placement can fit (scene/PlacementCapacity.hpp), not the close-packing
// bound: a scene that passes here is placed.
void Checker::placement() const {
  const double d = s_.particles.diameter;
  const auto& box = s_.container;
  const long long n = s_.particles.count;
  const TriangularLattice resting(box.width, box.height, d, box.periodic_x);
  const bool fully_periodic = box.periodic_x && box.periodic_z;
  if (s_.initial.placement == InitialPlacement::Lattice) {
    if (fully_periodic && !SquareLattice(n, box.width, box.height).fits(d))
      fail("particles.count", std::to_string(n),
           "more particles than fit on the square lattice of initial.placement = \"lattice\" "
           "in this periodic box (a spacing would be below one diameter)");
    if (!fully_periodic && n > resting.capacity())
      fail("particles.count", std::to_string(n),
           fmt::format("more particles than fit: the lattice of initial.placement = \"lattice\" "
                       "holds at most {} in this container",
                       resting.capacity()));
    return;
  }
  const double disk = std::numbers::pi * d * d / 4.0;
  const auto reachable =
      static_cast<long long>(kRandomJammingCoverage * box.width * box.height / disk);
  if (n > reachable)
    fail("particles.count", std::to_string(n),
         fmt::format(
             "more particles than initial.placement = \"random\" can place: random "
             "placement jams at {} of the area (at most {} here); use initial.placement "
             "= \"lattice\"{}",
             kRandomJammingCoverage, reachable,
             fully_periodic ? std::string() : fmt::format(" (at most {})", resting.capacity())));
}

// A box periodic along gravity has no floor: the layer falls for ever, and each particle that
// wraps from the bottom to the top gains m g H of potential energy from nowhere, so the
// energy balance (and any steady state) is meaningless. Without gravity the same box is a
// free gas (homogeneous cooling, the effective-restitution study).
void Checker::fallingBox() const {
  if (!s_.container.periodic_z || s_.run.gravity == 0) return;
  fail("container.periodic_z", "true",
       fmt::format("a box periodic along gravity (run.gravity = {}) has no floor: the layer "
                   "falls for ever and gains m g H at each wrap; set run.gravity = 0 or "
                   "container.periodic_z = false",
                   tomlNumber(s_.run.gravity)));
}

}  // namespace

void validateScene(const Scene& scene, const SceneOrigins& origins) {
  Checker check(scene, origins);
  check.singleKeys();
  check.temperature();
  check.records();
  check.geometry();
  check.placement();
  check.drive();
  check.fallingBox();
}

}  // namespace detail

void validateScene(const Scene& scene, std::string_view origin) {
  detail::validateScene(scene, detail::SceneOrigins{std::string(origin), false, {}});
}

}  // namespace granwave
