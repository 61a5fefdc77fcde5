#include "studies/hydro_run/LabFrame.hpp"

#include <algorithm>
#include <cmath>

namespace granwave {

void mapToLab(const hydro::HydroPhase& ph, double height, const FieldGrid& grid,
              double plate_velocity, double mass, std::vector<double>& nu, std::vector<double>& T,
              std::vector<double>& uz) {
  const std::size_t N = ph.z.size();
  for (int j = 0; j < grid.nz; ++j) {
    const double zp = grid.zCentre(j) - ph.plate_height;  // z' above the plate
    if (zp < ph.layer_bottom || zp > ph.layer_top || zp < 0 || zp > height) {
      nu.push_back(0.0);
      T.push_back(kNaN);
      uz.push_back(kNaN);
      continue;
    }
    const auto above = std::upper_bound(ph.z.begin(), ph.z.end(), zp);
    const std::size_t i =
        std::min<std::size_t>(std::max<std::ptrdiff_t>(above - ph.z.begin(), 1) - 1, N - 2);
    const double w = std::clamp((zp - ph.z[i]) / (ph.z[i + 1] - ph.z[i]), 0.0, 1.0);
    auto lerp = [&](const std::vector<double>& v) { return (1 - w) * v[i] + w * v[i + 1]; };
    nu.push_back(lerp(ph.area_fraction));
    T.push_back(mass * lerp(ph.theta));  // T = m theta, J: the ED's T_g
    uz.push_back(lerp(ph.u) + plate_velocity);
  }
}

PhaseProfiles labFrameProfiles(const Scene& scene, const SceneDerived& dv,
                               const hydro::HydroResult& r, int samples_per_cycle) {
  const FieldGrid grid = FieldGrid::forContainer(scene.container.width, scene.container.height,
                                                 dv.amplitude, scene.particles.diameter);
  PhaseProfiles p;
  PhaseFields& lab = p.pooled;
  lab.phases = static_cast<int>(r.window.size());
  lab.nz = grid.nz;
  lab.nx = 1;
  const double dt = 1.0 / (samples_per_cycle * scene.drive.frequency);
  const int window_cycles = r.periodic ? r.period : 2;  // HydroSimulation's window
  for (const hydro::HydroPhase& ph : r.window) {
    const double vb = dv.amplitude * dv.omega * std::cos(dv.omega * ph.time);
    mapToLab(ph, scene.container.height, grid, vb, dv.mass, lab.profile_area_fraction,
             lab.profile_temperature, lab.profile_velocity_z);
    p.plate_height.push_back(ph.plate_height);
    lab.center_of_mass_height.push_back(ph.center_of_mass_height + ph.plate_height);
    p.time.push_back(ph.time - r.window.front().time + dt);
    p.phase.push_back(static_cast<double>(p.phase.size() + 1) * window_cycles / lab.phases);
  }
  p.fronts = frontEpisodes(lab, {}, grid.z0, grid.wz, dv.T0, dt, {}, p.plate_height);
  for (int j = 0; j < grid.nz; ++j) p.z.push_back(grid.zCentre(j));
  p.front_height =
      frontHeights(lab, grid.z0, grid.wz, dv.T0, FrontOptions{}, &p.front_peak_temperature);
  return p;
}

}  // namespace granwave
