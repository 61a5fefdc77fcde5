#include "studies/run_files/RunOutputs.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "particles/H5mdReader.hpp"

namespace granwave {

LammpsTrajectory readLammpsTrajectory(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open the LAMMPS output");
  LammpsTrajectory r;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream row(line);
    double step = 0, t = 0, zb = 0, com = 0;
    if (!(row >> step >> t >> zb >> com))
      throw std::runtime_error(path + ": malformed line '" + line + "' (expected step t z_b com)");
    r.last_step = step;
    r.time.push_back(t);
    r.plate.push_back(zb);
    r.com.push_back(com);
  }
  return r;
}

Frame readLastFrame(const std::string& path) {
  const H5mdReader run(path);
  Frame fr;
  if (run.frameCount() == 0) return fr;
  const Snapshot last = run.frame(run.frameCount() - 1);
  fr.x = last.x;
  fr.z = last.z;
  fr.plate = last.plate_height;
  return fr;
}

RunObservables readRunObservables(const std::string& path) {
  const H5mdReader run(path);
  RunObservables r;
  const TimeSeries com = run.observable("center_of_mass_height");
  r.time = com.time;
  r.com_height = com.value;
  r.kinetic_energy = run.observable("kinetic_energy").value;
  r.dissipated_energy = run.observable("dissipated_energy").value;
  r.pair_impact_energy = run.observable("pair_impact_energy").value;
  r.pair_impact_loss = run.observable("pair_impact_loss").value;
  // Counters come as doubles, exact below 2^53 events.
  const std::vector<double> events = run.observable("events").value;
  if (!events.empty()) r.events = static_cast<std::uint64_t>(events.back());
  r.pair_count = run.observable("collisions/pair").value;
  r.tc_elastic_count = run.observable("collisions/tc_elastic").value;
  const std::vector<double> walls = run.observable("collisions/wall").value;
  if (!r.pair_count.empty()) {
    r.pair_collisions = static_cast<std::uint64_t>(r.pair_count.back());
    r.wall_collisions = static_cast<std::uint64_t>(walls.back());
    r.tc_elastic = static_cast<std::uint64_t>(r.tc_elastic_count.back());
  }
  return r;
}

}  // namespace granwave
