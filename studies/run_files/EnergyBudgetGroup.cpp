#include "studies/run_files/EnergyBudgetGroup.hpp"

#include <string>

namespace granwave {

namespace {

const std::string kBudget = "/budget";

void put(h5::File& f, const std::string& name, const std::vector<double>& v) {
  const std::string path = kBudget + "/" + name;
  f.writeDataset(path, v, {v.size()});
  f.writeStringAttribute(path, "unit", "J");
}

double sum(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return s;
}

}  // namespace

void RunEnergyBudget::addPhase(double width, double work, double collisional, double friction,
                               double wall, double side_wall, double change) {
  plate_work.push_back(width * work);
  collisional_loss.push_back(width * collisional);
  friction_loss.push_back(width * friction);
  wall_loss.push_back(width * (wall + side_wall));
  energy_change.push_back(width * change);
}

RunEnergyBudget::PerCycle RunEnergyBudget::perCycle(int window_cycles) const {
  const double per = 1e3 / window_cycles;
  PerCycle p{per * sum(plate_work), per * sum(collisional_loss), per * sum(friction_loss),
             per * sum(wall_loss),  per * sum(energy_change),    0};
  p.closure = p.change - (p.work - p.lost());
  return p;
}

void writeEnergyBudget(h5::File& f, const RunEnergyBudget& b) {
  if (b.empty()) return;
  f.createGroup(kBudget);
  put(f, "plate_work", b.plate_work);
  put(f, "collisional_loss", b.collisional_loss);
  put(f, "friction_loss", b.friction_loss);
  put(f, "wall_loss", b.wall_loss);
  put(f, "energy_change", b.energy_change);
}

RunEnergyBudget readEnergyBudget(const h5::File& f) {
  RunEnergyBudget b;
  if (!f.isGroup(kBudget)) return b;
  b.plate_work = f.readDataset<double>(kBudget + "/plate_work");
  b.collisional_loss = f.readDataset<double>(kBudget + "/collisional_loss");
  b.friction_loss = f.readDataset<double>(kBudget + "/friction_loss");
  b.wall_loss = f.readDataset<double>(kBudget + "/wall_loss");
  b.energy_change = f.readDataset<double>(kBudget + "/energy_change");
  return b;
}

}  // namespace granwave
