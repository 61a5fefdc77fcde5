// Scene file -> Scene: TOML syntax (toml++), `--set` overrides merged into the parsed table,
// one reader per key (the table kFields below is the list of valid keys), then the semantic
// checks of SceneValidation.cpp. Errors carry "file:line" of the offending value.
#include "scene/SceneParser.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <toml++/toml.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>
#include <utility>

#include "scene/NameSuggestion.hpp"
#include "scene/SceneDetail.hpp"
#include "scene/SceneEntry.hpp"

namespace granwave {
namespace {

using detail::SceneOrigins;

using detail::Entry;
using detail::nodeText;

void readTc(Scene& s, const Entry& e) {
  auto& c = s.contact;
  if (auto str = e.string()) {
    if (*str != "auto" && *str != "off") e.expected(R"("auto", "off" or a time in seconds)");
    c.tc_enabled = *str == "auto";
    c.tc_time.reset();
    return;
  }
  c.tc_enabled = true;
  c.tc_time = e.number();
}

void readTemperature(Scene& s, const Entry& e) {
  if (auto str = e.string()) {
    if (*str != "paper") e.expected(R"("paper" or an energy in J)");
    s.initial.temperature.reset();
    return;
  }
  s.initial.temperature = e.number();
}

void readRestitution(Scene& s, const Entry& e) {
  using K = RestitutionKind;
  s.contact.restitution =
      e.choice<K>({{"constant", K::Constant}, {"dry", K::Dry}, {"wet", K::Wet}});
}

ContactTangential tangentialChoice(const Entry& e) {
  using T = ContactTangential;
  return e.choice<T>(
      {{"smooth", T::Smooth}, {"rough-elastic", T::RoughElastic}, {"coulomb", T::Coulomb}});
}

void readWallTangential(Scene& s, const Entry& e) {
  s.contact.wall_tangential = tangentialChoice(e);
}
void readTcTangential(Scene& s, const Entry& e) { s.contact.tc_tangential = tangentialChoice(e); }

// Older key: true = the particles' friction law at the walls ("coulomb"), false = "smooth".
void readRoughWalls(Scene& s, const Entry& e) {
  s.contact.wall_tangential = e.boolean() ? ContactTangential::Coulomb : ContactTangential::Smooth;
}

void readTcWindow(Scene& s, const Entry& e) {
  using W = TcWindow;
  s.contact.tc_window = e.choice<W>({{"rolling", W::Rolling}, {"anchored", W::Anchored}});
}

void readSleep(Scene& s, const Entry& e) {
  using R = SleepRule;
  s.contact.sleep = e.choice<R>({{"auto", R::Auto}, {"on", R::On}, {"off", R::Off}});
}

void readKappaUnits(Scene& s, const Entry& e) {
  using K = KappaUnits;
  s.contact.kappa_units = e.choice<K>({{"si", K::Si}, {"gd", K::GravityDiameter}, {"cgs", K::Cgs}});
}

void readPlacement(Scene& s, const Entry& e) {
  using P = InitialPlacement;
  s.initial.placement = e.choice<P>({{"random", P::Random}, {"lattice", P::Lattice}});
}

void readHydroModel(Scene& s, const Entry& e) {
  using M = HydroRestitutionModel;
  s.hydro.restitution_model = e.choice<M>({{"constant", M::Constant}, {"velocity", M::Velocity}});
}

void readHydroTransport(Scene& s, const Entry& e) {
  using T = HydroTransport;
  s.hydro.transport =
      e.choice<T>({{"jenkins-richman", T::JenkinsRichman}, {"garzo-dufty", T::GarzoDufty}});
}

void readHydroPairCorrelation(Scene& s, const Entry& e) {
  using G = HydroPairCorrelation;
  s.hydro.pair_correlation = e.choice<G>({{"luding", G::Luding}, {"henderson", G::Henderson}});
}

void readHydroParticles(Scene& s, const Entry& e) {
  using P = HydroParticles;
  s.hydro.particles = e.choice<P>({{"smooth", P::Smooth}, {"rough", P::Rough}});
}

void readHydroWalls(Scene& s, const Entry& e) {
  using W = HydroWalls;
  s.hydro.walls = e.choice<W>({{"spring", W::Spring}, {"hard", W::Hard}});
}

void readHydroStart(Scene& s, const Entry& e) {
  using St = HydroStart;
  s.hydro.start = e.choice<St>({{"settled", St::Settled}, {"spread", St::Spread}});
}

void readSeed(Scene& s, const Entry& e) { s.run.seed = e.integer<std::int64_t>(0); }

// Readers of plain fields, given as (section member, field member) pointers.
template <auto Section, auto Member>
void number(Scene& s, const Entry& e) {
  (s.*Section).*Member = e.number();
}
template <auto Section, auto Member>
void integer(Scene& s, const Entry& e) {
  (s.*Section).*Member = e.integer<int>();
}
template <auto Section, auto Member>
void boolean(Scene& s, const Entry& e) {
  (s.*Section).*Member = e.boolean();
}

using Reader = void (*)(Scene&, const Entry&);
struct Field {
  std::string_view section, name;
  Reader read;
};

constexpr auto kP = &Scene::particles;
constexpr auto kB = &Scene::container;
constexpr auto kD = &Scene::drive;
constexpr auto kC = &Scene::contact;
constexpr auto kR = &Scene::run;
constexpr auto kH = &Scene::hydro;
using CS = ContactSpec;

// Every valid key, in the order of docs/scenes.md.
const Field kFields[] = {
    {"particles", "count", integer<kP, &ParticlesSpec::count>},
    {"particles", "diameter", number<kP, &ParticlesSpec::diameter>},
    {"particles", "density", number<kP, &ParticlesSpec::density>},
    {"particles", "youngs_modulus", number<kP, &ParticlesSpec::youngs_modulus>},
    {"particles", "poisson_ratio", number<kP, &ParticlesSpec::poisson_ratio>},
    {"container", "width", number<kB, &ContainerSpec::width>},
    {"container", "height", number<kB, &ContainerSpec::height>},
    {"container", "periodic_x", boolean<kB, &ContainerSpec::periodic_x>},
    {"container", "periodic_z", boolean<kB, &ContainerSpec::periodic_z>},
    {"drive", "frequency", number<kD, &DriveSpec::frequency>},
    {"drive", "gamma", number<kD, &DriveSpec::gamma>},
    {"drive", "amplitude", number<kD, &DriveSpec::amplitude>},
    {"contact", "restitution", readRestitution},
    {"contact", "e", number<kC, &CS::e>},
    {"contact", "kappa", number<kC, &CS::kappa>},
    {"contact", "kappa_units", readKappaUnits},
    {"contact", "e_inf", number<kC, &CS::e_inf>},
    {"contact", "stokes_critical", number<kC, &CS::stokes_critical>},
    {"contact", "viscosity", number<kC, &CS::viscosity>},
    {"contact", "friction", number<kC, &CS::friction>},
    {"contact", "tangential_limit", number<kC, &CS::tangential_limit>},
    {"contact", "wall_tangential", readWallTangential},
    {"contact", "rough_walls", readRoughWalls},
    {"contact", "tc", readTc},
    {"contact", "tc_tangential", readTcTangential},
    {"contact", "tc_window", readTcWindow},
    {"contact", "sleep", readSleep},
    {"contact", "rest_velocity", number<kC, &CS::rest_velocity>},
    {"initial", "temperature", readTemperature},
    {"initial", "placement", readPlacement},
    {"run", "duration", number<kR, &RunSpec::duration>},
    {"run", "phases_per_cycle", integer<kR, &RunSpec::phases_per_cycle>},
    {"run", "record_interval", number<kR, &RunSpec::record_interval>},
    {"run", "trajectory_stride", integer<kR, &RunSpec::trajectory_stride>},
    {"run", "seed", readSeed},
    {"run", "gravity", number<kR, &RunSpec::gravity>},
    {"hydro", "dimensions", integer<kH, &HydroSpec::dimensions>},
    {"hydro", "cells", integer<kH, &HydroSpec::cells>},
    {"hydro", "columns", integer<kH, &HydroSpec::columns>},
    {"hydro", "perturbation", number<kH, &HydroSpec::perturbation>},
    {"hydro", "remap_share", number<kH, &HydroSpec::remap_share>},
    {"hydro", "rtol", number<kH, &HydroSpec::rtol>},
    {"hydro", "atol", number<kH, &HydroSpec::atol>},
    {"hydro", "restitution_model", readHydroModel},
    {"hydro", "transport", readHydroTransport},
    {"hydro", "side_walls", boolean<kH, &HydroSpec::side_walls>},
    {"hydro", "energy_budget", boolean<kH, &HydroSpec::energy_budget>},
    {"hydro", "pair_correlation", readHydroPairCorrelation},
    {"hydro", "contact_pressure", number<kH, &HydroSpec::contact_pressure>},
    {"hydro", "particles", readHydroParticles},
    {"hydro", "start", readHydroStart},
    {"hydro", "initial_temperature", number<kH, &HydroSpec::initial_temperature>},
    {"hydro", "artificial_viscosity", number<kH, &HydroSpec::artificial_viscosity>},
    {"hydro", "walls", readHydroWalls},
    {"hydro", "wall_contact_range", number<kH, &HydroSpec::wall_contact_range>},
    {"hydro", "wall_contact_stiffness", number<kH, &HydroSpec::wall_contact_stiffness>},
    {"hydro", "packing_width", number<kH, &HydroSpec::packing_width>},
    {"hydro", "temperature_floor", number<kH, &HydroSpec::temperature_floor>},
};

const Field* findField(std::string_view section, std::string_view name) {
  for (const auto& f : kFields)
    if (f.section == section && f.name == name) return &f;
  return nullptr;
}

bool isSection(std::string_view name) {
  return std::any_of(std::begin(kFields), std::end(kFields),
                     [name](const Field& f) { return f.section == name; });
}

std::vector<std::string> sectionNames() {
  std::vector<std::string> names;
  for (const auto& f : kFields)
    if (names.empty() || names.back() != f.section) names.emplace_back(f.section);
  return names;
}

std::string unknownSection(std::string_view section) {
  const auto names = sectionNames();
  return fmt::format("unknown section [{}]{}; valid sections: {}", section,
                     didYouMean(section, names), fmt::join(names, ", "));
}

// "unknown key 'drive.gama' (did you mean 'drive.gamma'?); valid keys in [drive]: ..."
std::string unknownKey(std::string_view section, std::string_view name) {
  std::vector<std::string> inSection, everywhere;
  for (const auto& f : kFields) {
    everywhere.push_back(fmt::format("{}.{}", f.section, f.name));
    if (f.section == section) inSection.push_back(everywhere.back());
  }
  const std::string key = fmt::format("{}.{}", section, name);
  std::string hint = didYouMean(key, inSection);
  // A key put in the wrong section: suggest where it belongs.
  for (const auto& f : kFields)
    if (hint.empty() && f.name == name)
      hint = fmt::format(" (did you mean '{}.{}'?)", f.section, f.name);
  std::vector<std::string_view> names;
  for (const auto& k : inSection) names.push_back(std::string_view(k).substr(section.size() + 1));
  return fmt::format("unknown key '{}'{}; valid keys in [{}]: {}", key, hint, section,
                     fmt::join(names, ", "));
}

std::string lineOf(const SceneOrigins& o, const toml::node& node) {
  const auto& begin = node.source().begin;
  return begin ? fmt::format("{}:{}", o.file, begin.line) : o.file;
}

toml::table parseToml(std::string_view text, const std::string& file) {
  try {
    return toml::parse(text, file);
  } catch (const toml::parse_error& err) {
    const auto& begin = err.source().begin;
    throw SceneError(fmt::format("{}:{}:{}: TOML syntax error: {}", file, begin.line, begin.column,
                                 err.description()));
  }
}

std::string trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return "";
  return std::string(text.substr(first, text.find_last_not_of(" \t") - first + 1));
}

// The value of "--set key=value" as a table {v = value}: a TOML value, or else the raw text
// as a string (so that contact.restitution=wet needs no quotes).
toml::table overrideValue(const std::string& text) {
  try {
    toml::table t = toml::parse("v = " + text);
    if (t.size() == 1 && t.contains("v")) return t;
  } catch (const toml::parse_error&) {
  }
  return toml::table{{"v", text}};
}

// Merges the overrides into the parsed file. An override of drive.amplitude drops a gamma
// given in the file and vice versa (giving both in one place stays an error).
void applyOverrides(toml::table& root, const std::vector<std::string>& overrides,
                    SceneOrigins& origins) {
  std::set<std::string, std::less<>> given;
  for (const std::string& text : overrides) {
    const auto eq = text.find('=');
    const auto dot = text.find('.');
    const std::string section = trim(text.substr(0, std::min(dot, eq)));
    const std::string name = dot < eq ? trim(text.substr(dot + 1, eq - dot - 1)) : "";
    if (eq == std::string::npos || section.empty() || name.empty()) {
      throw SceneError(fmt::format(
          "{}: --set '{}': expected section.key=value (e.g. drive.gamma=3.5)", origins.file, text));
    }
    if (!isSection(section))
      throw SceneError(
          fmt::format("{}: --set {}: {}", origins.file, text, unknownSection(section)));
    if (!findField(section, name))
      throw SceneError(
          fmt::format("{}: --set {}: {}", origins.file, text, unknownKey(section, name)));
    if (!root.contains(section)) root.insert(section, toml::table{});
    auto* table = root.get(section)->as_table();
    if (!table) continue;  // the file's own error ("expected a table") is reported by readScene
    table->insert_or_assign(name, *overrideValue(trim(text.substr(eq + 1))).get("v"));
    const std::string key = fmt::format("{}.{}", section, name);
    given.insert(key);
    origins.where[key] = fmt::format("{} (--set)", origins.file);
  }
  if (auto* drive = root["drive"].as_table()) {
    if (given.count("drive.amplitude") && !given.count("drive.gamma")) drive->erase("gamma");
    if (given.count("drive.gamma") && !given.count("drive.amplitude")) drive->erase("amplitude");
  }
}

void readSection(Scene& scene, std::string_view section, const toml::table& table,
                 SceneOrigins& origins) {
  for (const auto& [k, node] : table) {
    const std::string key = fmt::format("{}.{}", section, k.str());
    const auto it = origins.where.try_emplace(key, lineOf(origins, node)).first;
    const Field* field = findField(section, k.str());
    if (!field) throw SceneError(fmt::format("{}: {}", it->second, unknownKey(section, k.str())));
    field->read(scene, Entry(node, key, it->second));
  }
  if (section == "drive" && table.contains("amplitude")) {
    if (table.contains("gamma")) {
      throw SceneError(
          fmt::format("{}: drive.gamma = {} and drive.amplitude = {}: give one of them, not both",
                      origins.where["drive.amplitude"], nodeText(*table.get("gamma")),
                      nodeText(*table.get("amplitude"))));
    }
    scene.drive.gamma.reset();
  }
}

Scene readScene(const toml::table& root, SceneOrigins& origins) {
  Scene scene;
  for (const auto& [k, node] : root) {
    const std::string where = lineOf(origins, node), name(k.str());
    const auto* table = node.as_table();
    if (table && isSection(name)) {
      readSection(scene, name, *table, origins);
    } else if (isSection(name)) {
      throw SceneError(
          fmt::format("{}: {} = {}: expected a table [{}]", where, name, nodeText(node), name));
    } else if (table) {
      throw SceneError(fmt::format("{}: {}", where, unknownSection(name)));
    } else {
      for (const auto& f : kFields)
        if (f.name == name)
          throw SceneError(fmt::format("{}: {} = {} outside any section: write it under [{}]",
                                       where, name, nodeText(node), f.section));
      throw SceneError(
          fmt::format("{}: unknown top-level key '{}' = {}; keys belong in the sections {}", where,
                      name, nodeText(node), fmt::join(sectionNames(), ", ")));
    }
  }
  return scene;
}

}  // namespace

Scene parseSceneString(std::string_view text, const std::vector<std::string>& overrides,
                       std::string_view origin) {
  SceneOrigins origins{std::string(origin), true, {}};
  toml::table root = parseToml(text, origins.file);
  applyOverrides(root, overrides, origins);
  Scene scene = readScene(root, origins);
  detail::validateScene(scene, origins);
  return scene;
}

Scene parseSceneFile(const std::string& path, const std::vector<std::string>& overrides) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(fmt::format("{}: cannot open scene file", path));
  std::ostringstream text;
  text << in.rdbuf();
  Scene scene = parseSceneString(text.str(), overrides, path);
  const bool named_in_file = toml::parse(text.str())["contact"]["restitution"].is_value();
  const bool named_by_override =
      std::any_of(overrides.begin(), overrides.end(), [](const std::string& o) {
        return o.rfind("contact.restitution=", 0) == 0 || o.rfind("contact.restitution =", 0) == 0;
      });
  if (!named_in_file && !named_by_override)
    throw SceneError(fmt::format(
        "{}: {}names no restitution law; add [contact] restitution = \"dry\" (or \"wet\", "
        "\"constant\") or --set contact.restitution=dry",
        path, text.str().find_first_not_of(" \t\r\n") == std::string::npos ? "is empty and " : ""));
  return scene;
}

}  // namespace granwave
