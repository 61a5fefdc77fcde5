// Semantic checks of a complete scene (after file and overrides): ranges of single keys first,
// then geometry (the container must hold a particle and the particles), drive and packing.
// Each failure names the key, its value and origin, and what is valid (docs/scenes.md).
#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <tuple>

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

// Hexagonal close packing of equal disks, pi / (2 sqrt 3): the densest 2D packing.
constexpr double kHexagonalPacking = 0.9069;

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
  void within(std::string_view key, double v, char open, double lo, double hi, char close) const {
    const bool okLo = open == '[' ? v >= lo : v > lo;
    const bool okHi = close == ']' ? v <= hi : v < hi;
    if (!(okLo && okHi)) {
      fail(key, v,
           fmt::format("must be in {}{}, {}{}", open, tomlNumber(lo), tomlNumber(hi), close));
    }
  }
  void atLeast(std::string_view key, long long v, long long min) const {
    if (v < min) fail(key, std::to_string(v), fmt::format("must be an integer >= {}", min));
  }

  void singleKeys() const;
  void drive() const;
  void geometry() const;

 private:
  const Scene& s_;
  const SceneOrigins& o_;
};

void Checker::singleKeys() const {
  const auto& p = s_.particles;
  const auto& c = s_.contact;
  atLeast("particles.count", p.count, 1);
  positive("particles.diameter", p.diameter, "m");
  positive("particles.density", p.density, "kg/m^3");
  positive("particles.youngs_modulus", p.youngs_modulus, "Pa");
  within("particles.poisson_ratio", p.poisson_ratio, '(', -1.0, 0.5, ')');
  positive("container.width", s_.container.width, "m");
  positive("container.height", s_.container.height, "m");
  nonNegative("drive.frequency", s_.drive.frequency, "Hz; 0 = no drive");
  if (s_.drive.gamma) nonNegative("drive.gamma", *s_.drive.gamma, "peak acceleration / g");
  if (s_.drive.amplitude) nonNegative("drive.amplitude", *s_.drive.amplitude, "m");
  within("contact.e", c.e, '[', 0.0, 1.0, ']');
  nonNegative("contact.kappa", c.kappa, "dimensionless in the unit of contact.kappa_units");
  if (c.kappa_units == KappaUnits::GravityDiameter && !(s_.run.gravity > 0))
    fail("contact.kappa_units", "\"gd\"",
         "the unit sqrt(g d) needs run.gravity > 0; use \"si\" or \"cgs\"");
  within("contact.e_inf", c.e_inf, '(', 0.0, 1.0, ']');
  nonNegative("contact.stokes_critical", c.stokes_critical, "dimensionless");
  positive("contact.viscosity", c.viscosity, "Pa s");
  nonNegative("contact.friction", c.friction, "0 = no rotation");
  within("contact.tangential_limit", c.tangential_limit, '[', -1.0, 1.0, ']');
  if (c.tc_enabled && c.tc_time) {
    if (!(*c.tc_time > 0 && std::isfinite(*c.tc_time)))
      fail("contact.tc", *c.tc_time, R"(must be "auto", "off" or a time in seconds > 0)");
  }
  nonNegative("contact.rest_velocity", c.rest_velocity, "m/s");
  if (s_.initial.temperature)
    nonNegative("initial.temperature", *s_.initial.temperature, "J per particle");
  positive("run.duration", s_.run.duration, "s");
  atLeast("run.phases_per_cycle", s_.run.phases_per_cycle, 1);
  nonNegative("run.record_interval", s_.run.record_interval, "s; 0 = duration / 100");
  atLeast("run.trajectory_stride", s_.run.trajectory_stride, 1);
  if (s_.run.seed > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
    fail("run.seed", std::to_string(s_.run.seed), "must be an integer in [0, 2^63 - 1]");
  nonNegative("run.gravity", s_.run.gravity, "m/s^2, magnitude");
  atLeast("hydro.cells", s_.hydro.cells, 8);
  positive("hydro.rtol", s_.hydro.rtol, "relative tolerance");
  positive("hydro.atol", s_.hydro.atol, "absolute tolerance");
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
    if (periodic && length < 3 * d) {
      fail(key, length,
           fmt::format("a periodic length must be at least 3 particle diameters ({} m): the "
                       "engine's 3 x 3 cell stencil needs 3 cells of side >= d",
                       tomlNumber(3 * d)));
    }
  }
  const double occupied = s_.particles.count * std::numbers::pi * d * d / 4.0;
  const double available = kHexagonalPacking * box.width * box.height;
  if (occupied > available) {
    fail("particles.count", std::to_string(s_.particles.count),
         fmt::format("more particles than fit: N pi d^2/4 = {:.4g} m^2 exceeds the hexagonal close "
                     "packing limit 0.9069 x width x height = {:.4g} m^2 (at most {} particles)",
                     occupied, available,
                     static_cast<long long>(available / (std::numbers::pi * d * d / 4.0))));
  }
}

}  // namespace

void validateScene(const Scene& scene, const SceneOrigins& origins) {
  Checker check(scene, origins);
  check.singleKeys();
  check.geometry();
  check.drive();
}

}  // namespace detail

void validateScene(const Scene& scene, std::string_view origin) {
  detail::validateScene(scene, detail::SceneOrigins{std::string(origin), false, {}});
}

}  // namespace granwave
