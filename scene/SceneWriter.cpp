// Scene -> TOML: every key written, so that a stored scene reproduces its run, with units in
// comments and the derived quantities (SceneDerived) for the reader.
#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <string>

#include "scene/SceneDerived.hpp"
#include "scene/SceneDetail.hpp"
#include "scene/SceneParser.hpp"

namespace granwave {
namespace detail {

std::string tomlNumber(double value) {
  // Shortest text that reads back exactly; large values in exponent form (63e9 -> 6.3e+10).
  std::string text = fmt::format("{}", value);
  if (std::isfinite(value) && std::abs(value) >= 1e6) {
    char buffer[32];
    const auto end =
        std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::scientific).ptr;
    text.assign(buffer, end);
  }
  if (text.find_first_of(".eni") == std::string::npos) text += ".0";
  return text;
}

}  // namespace detail

namespace {

using detail::tomlNumber;

class TomlWriter {
 public:
  void section(std::string_view name) { out_ += fmt::format("\n[{}]\n", name); }
  void key(std::string_view name, std::string_view value, std::string_view comment = {}) {
    const std::string line = fmt::format("{} = {}", name, value);
    out_ += comment.empty() ? line + "\n" : fmt::format("{:<34}# {}\n", line, comment);
  }
  void key(std::string_view name, double value, std::string_view comment = {}) {
    key(name, tomlNumber(value), comment);
  }
  void key(std::string_view name, bool value, std::string_view comment = {}) {
    key(name, std::string_view(value ? "true" : "false"), comment);
  }
  void integer(std::string_view name, long long value, std::string_view comment = {}) {
    key(name, std::to_string(value), comment);
  }
  void comment(std::string_view text) { out_ += fmt::format("# {}\n", text); }
  std::string take() { return std::move(out_); }

 private:
  std::string out_;
};

std::string quoted(std::string_view word) { return fmt::format("\"{}\"", word); }

const char* name(RestitutionKind k) {
  return k == RestitutionKind::Constant ? "constant" : k == RestitutionKind::Dry ? "dry" : "wet";
}

const char* name(ContactTangential t) {
  return t == ContactTangential::Smooth         ? "smooth"
         : t == ContactTangential::RoughElastic ? "rough-elastic"
                                                : "coulomb";
}
const char* name(KappaUnits k) {
  return k == KappaUnits::Si ? "si" : k == KappaUnits::GravityDiameter ? "gd" : "cgs";
}

void writeDrive(TomlWriter& w, const DriveSpec& drive, const SceneDerived& d) {
  w.section("drive");
  w.key("frequency", drive.frequency, "Hz, f (0 = no drive)");
  if (drive.amplitude) {
    w.key("amplitude", *drive.amplitude, "m, A");
    if (d.driven) w.comment(fmt::format("derived: gamma = {:.6g}", d.gamma));
  } else if (drive.gamma) {
    w.key("gamma", *drive.gamma, "peak plate acceleration / g");
    if (d.driven) w.comment(fmt::format("derived: amplitude = {:.6g} m", d.amplitude));
  }
}

void writeContact(TomlWriter& w, const ContactSpec& c, const SceneDerived& d) {
  w.section("contact");
  w.key("restitution", quoted(name(c.restitution)), R"("constant" | "dry" | "wet")");
  w.key("e", c.e, "constant law");
  w.key("kappa", c.kappa, "dry law: e = 1 - kappa (v_n/u)^(1/5)");
  w.key("kappa_units", quoted(name(c.kappa_units)),
        fmt::format(R"(u: "si" 1 m/s | "gd" sqrt(g d) | "cgs" 1 cm/s; kappa_SI = {:.6g})",
                    d.kappa_si));
  w.key("e_inf", c.e_inf, "wet law");
  w.key("stokes_critical", c.stokes_critical, "wet law, St_c");
  w.key("viscosity", c.viscosity, "Pa s, eta");
  w.key("friction", c.friction, "mu (0 = no rotation)");
  w.key("tangential_limit", c.tangential_limit, "e_t0 (Luding: -1 smooth, +1 rough)");
  w.key("wall_tangential", quoted(name(c.wall_tangential)),
        R"("smooth" | "rough-elastic" | "coulomb")");
  if (!c.tc_enabled) {
    w.key("tc", quoted("off"), R"("auto" | "off" | seconds)");
  } else if (c.tc_time) {
    w.key("tc", *c.tc_time, "s, TC time");
  } else {
    w.key("tc", quoted("auto"), fmt::format("t_c = {:.4g} s", d.tc));
  }
  w.key("tc_tangential", quoted(name(c.tc_tangential)),
        R"(TC collisions: "smooth" | "rough-elastic" | "coulomb")");
  w.key("tc_window", quoted(c.tc_window == TcWindow::Rolling ? "rolling" : "anchored"),
        R"("rolling" | "anchored")");
  const char* sleep[] = {"auto", "on", "off"};
  w.key("sleep", quoted(sleep[static_cast<int>(c.sleep)]), R"("auto" | "on" | "off")");
  w.key("rest_velocity", c.rest_velocity, "m/s");
}

}  // namespace

std::string sceneToToml(const Scene& s) {
  const SceneDerived d = derive(s);
  TomlWriter w;
  w.comment("granwave scene, complete and resolved (SI units; see docs/scenes.md)");
  w.comment(
      fmt::format("derived: m = {:.6g} kg, v0 = {:.6g} m/s, T0 = {:.6g} J", d.mass, d.v0, d.T0));
  w.comment(fmt::format("         q = {:.6g} s/m, v_c = {:.6g} m/s", d.q, d.v_c));
  w.section("particles");
  w.integer("count", s.particles.count, "N");
  w.key("diameter", s.particles.diameter, "m, d");
  w.key("density", s.particles.density, "kg/m^3, rho_p");
  w.key("youngs_modulus", s.particles.youngs_modulus, "Pa, E");
  w.key("poisson_ratio", s.particles.poisson_ratio, "sigma");
  w.section("container");
  w.key("width", s.container.width, "m, L_x");
  w.key("height", s.container.height, "m, L_z");
  w.key("periodic_x", s.container.periodic_x);
  w.key("periodic_z", s.container.periodic_z);
  writeDrive(w, s.drive, d);
  writeContact(w, s.contact, d);
  w.section("initial");
  if (s.initial.temperature) {
    w.key("temperature", *s.initial.temperature, "J per particle (Maxwellian)");
  } else {
    w.key("temperature", quoted("paper"), "random speeds below 1e-2 sqrt(g d)");
  }
  w.key("placement",
        quoted(s.initial.placement == InitialPlacement::Random ? "random" : "lattice"));
  w.section("run");
  w.key("duration", s.run.duration, "s");
  w.integer("phases_per_cycle", s.run.phases_per_cycle, "M");
  w.key("record_interval", s.run.record_interval, "s, undriven (0 = duration / 100)");
  w.integer("trajectory_stride", s.run.trajectory_stride);
  w.key("seed", std::to_string(s.run.seed), "random initial state");
  w.key("gravity", s.run.gravity, "m/s^2");
  w.section("hydro");
  w.integer("dimensions", s.hydro.dimensions);
  w.integer("cells", s.hydro.cells);
  w.integer("columns", s.hydro.columns);
  w.key("perturbation", s.hydro.perturbation);
  w.key("remap_share", s.hydro.remap_share);
  w.key("rtol", s.hydro.rtol);
  w.key("atol", s.hydro.atol);
  w.key("restitution_model",
        quoted(s.hydro.restitution_model == HydroRestitutionModel::Constant ? "constant"
                                                                            : "velocity"));
  w.key("side_walls", s.hydro.side_walls);
  w.key("energy_budget", s.hydro.energy_budget);
  w.key("transport", quoted(s.hydro.transport == HydroTransport::GarzoDufty ? "garzo-dufty"
                                                                            : "jenkins-richman"));
  w.key(
      "pair_correlation",
      quoted(s.hydro.pair_correlation == HydroPairCorrelation::Henderson ? "henderson" : "luding"));
  w.key("contact_pressure", s.hydro.contact_pressure);
  w.key("particles", quoted(s.hydro.particles == HydroParticles::Rough ? "rough" : "smooth"));
  w.key("start", quoted(s.hydro.start == HydroStart::Spread ? "spread" : "settled"));
  w.key("initial_temperature", s.hydro.initial_temperature);
  w.key("artificial_viscosity", s.hydro.artificial_viscosity);
  w.key("walls", quoted(s.hydro.walls == HydroWalls::Hard ? "hard" : "spring"));
  w.key("wall_contact_range", s.hydro.wall_contact_range);
  w.key("wall_contact_stiffness", s.hydro.wall_contact_stiffness);
  w.key("packing_width", s.hydro.packing_width);
  w.key("temperature_floor", s.hydro.temperature_floor);
  return w.take();
}

}  // namespace granwave
