#include "studies/continuum_sensitivity/ContinuumSensitivityStudy.hpp"

#include <fmt/format.h>

#include <cmath>
#include <functional>
#include <map>
#include <sstream>

#include "studies/continuum_sensitivity/ContinuumSensitivityAnalysis.hpp"
#include "studies/continuum_sensitivity/ContinuumSensitivityReport.hpp"
#include "studies/statistics/Measurement.hpp"

namespace granwave {

namespace {

using KeyValue = std::function<double(const Scene&)>;

const std::map<std::string, KeyValue>& keyTable() {
  static const std::map<std::string, KeyValue> table{
      {"hydro.artificial_viscosity", [](const Scene& s) { return s.hydro.artificial_viscosity; }},
      {"hydro.wall_contact_range", [](const Scene& s) { return s.hydro.wall_contact_range; }},
      {"hydro.wall_contact_stiffness",
       [](const Scene& s) { return s.hydro.wall_contact_stiffness; }},
      {"hydro.packing_width", [](const Scene& s) { return s.hydro.packing_width; }},
      {"hydro.temperature_floor", [](const Scene& s) { return s.hydro.temperature_floor; }},
      {"hydro.contact_pressure", [](const Scene& s) { return s.hydro.contact_pressure; }},
      {"hydro.cells", [](const Scene& s) { return static_cast<double>(s.hydro.cells); }},
      {"hydro.rtol", [](const Scene& s) { return s.hydro.rtol; }},
      {"hydro.atol", [](const Scene& s) { return s.hydro.atol; }},
      {"hydro.initial_temperature", [](const Scene& s) { return s.hydro.initial_temperature; }},
  };
  return table;
}

// "a=1;b=2" -> {"a=1", "b=2"}, blanks dropped.
std::vector<std::string> splitOverrides(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ';')) {
    const auto first = item.find_first_not_of(' '), last = item.find_last_not_of(' ');
    if (first != std::string::npos) out.push_back(item.substr(first, last - first + 1));
  }
  return out;
}

int lawIndex(StudyFile& f, const std::string& law) {
  for (int k = 0; k < kLaws; ++k)
    if (law == kLawNames[k]) return k;
  f.fail("cases", "laws", "\"" + law + "\" is not a law; valid: \"dry\", \"wet\"");
}

void readCases(StudyFile& f, ContinuumSensitivityConfig& c) {
  const std::vector<std::string> names = f.strings("cases", "names", {"paper dry", "paper wet"});
  const std::vector<std::string> laws = f.strings("cases", "laws", {"dry", "wet"});
  const std::vector<std::string> sets =
      f.strings("cases", "sets", std::vector<std::string>(names.size()));
  if (laws.size() != names.size() || sets.size() != names.size())
    f.fail("cases", "laws", "names, laws and sets must have one entry per case");
  for (std::size_t k = 0; k < names.size(); ++k)
    c.cases.push_back({names[k], lawIndex(f, laws[k]), splitOverrides(sets[k])});
}

std::string variantValue(const std::string& key, double value) {
  return key == "hydro.cells" ? fmt::format("{}", static_cast<long>(std::lround(value)))
                              : formatCompact(value);
}

}  // namespace

const std::vector<std::string>& sensitivityKeys() {
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> k;
    for (const auto& [name, value] : keyTable()) k.push_back(name);
    return k;
  }();
  return keys;
}

double sensitivityKeyValue(const Scene& scene, const std::string& key) {
  const auto found = keyTable().find(key);
  if (found == keyTable().end()) {
    std::string valid;
    for (const std::string& k : sensitivityKeys()) valid += (valid.empty() ? "" : ", ") + k;
    throw StudyError("parameter " + key + " cannot be varied; valid: " + valid);
  }
  return found->second(scene);
}

ContinuumSensitivityStudy::ContinuumSensitivityStudy(StudyFile& f) {
  c_.scenes = LawScenes::read(f);
  readCases(f, c_);
  c_.parameters = f.strings("parameters", "keys", c_.parameters);
  c_.factors = f.numbers("parameters", "factors", c_.factors);
  c_.tolerance = f.number("parameters", "tolerance", c_.tolerance);
  c_.phases_per_cycle = f.integer("parameters", "phases_per_cycle", c_.phases_per_cycle);
  c_.front_fractions = f.numbers("parameters", "front_fractions", c_.front_fractions);
  bool increasing = c_.front_fractions.size() >= 2;
  for (std::size_t k = 0; k < c_.front_fractions.size(); ++k)
    increasing = increasing && c_.front_fractions[k] >= 0 && c_.front_fractions[k] <= 1 &&
                 (k == 0 || c_.front_fractions[k] > c_.front_fractions[k - 1]);
  if (!increasing)
    f.fail("parameters", "front_fractions",
           "expected at least two increasing mass fractions in [0, 1]");
  if (!(c_.tolerance > 0 && c_.tolerance < 1))
    f.fail("parameters", "tolerance", "expected a fraction in (0, 1)");
  for (double factor : c_.factors)
    if (!(factor > 0) || factor == 1) f.fail("parameters", "factors", "expected > 0 and != 1");
  c_.scenes.loadBase(f);
  for (const SensitivityCase& k : c_.cases) {
    // The study's sampling first, so that a case's own overrides (a finer sampling) win.
    std::vector<std::string> base{fmt::format("run.phases_per_cycle={}", c_.phases_per_cycle)};
    base.insert(base.end(), k.set.begin(), k.set.end());
    const Scene scene = c_.scenes.scene(f, k.law, base);
    std::vector<SensitivityVariant> vs{{"", 1, 0, hydroLabel(k.law, k.name + " | base")}};
    requests_.push_back(runRequest(RunKind::Hydro, vs.back().label, scene));
    for (const std::string& key : c_.parameters) {
      double value = 0;
      try {
        value = sensitivityKeyValue(scene, key);
      } catch (const StudyError& e) {
        f.fail("parameters", "keys", e.what());
      }
      for (double factor : c_.factors) {
        const std::string v = variantValue(key, value * factor);
        SensitivityVariant sv{
            key, factor, std::stod(v),
            hydroLabel(k.law, fmt::format("{} | {} x{}", k.name, key, formatCompact(factor)))};
        std::vector<std::string> set = base;
        set.push_back(key + "=" + v);
        requests_.push_back(runRequest(RunKind::Hydro, sv.label, c_.scenes.scene(f, k.law, set)));
        vs.push_back(sv);
      }
    }
    c_.variants.push_back(std::move(vs));
  }
}

void ContinuumSensitivityStudy::analyse(const RunSet& runs, h5::File& results,
                                        Report& report) const {
  const ContinuumSensitivityResults r = analyseContinuumSensitivity(c_, runs);
  writeContinuumSensitivityResults(results, c_, r);
  reportContinuumSensitivity(c_, r, report);
}

std::unique_ptr<Study> makeContinuumSensitivityStudy(StudyFile& file) {
  return std::make_unique<ContinuumSensitivityStudy>(file);
}

}  // namespace granwave
