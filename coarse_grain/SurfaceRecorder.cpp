#include "coarse_grain/SurfaceRecorder.hpp"

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "h5/H5Error.hpp"

namespace granwave {

SurfaceRecorder::SurfaceRecorder(const SurfaceRecorderConfig& c) : cfg_(c) {
  if (c.records_per_cycle < 1 || c.keep_cycles < 1 || !(c.width > 0) || !(c.diameter > 0))
    throw std::invalid_argument(
        "surface recorder needs records per cycle, kept cycles, width and diameter > 0");
  columns_ = std::max(1, static_cast<int>(std::lround(c.width / c.diameter)));
}

void SurfaceRecorder::observe(const Snapshot& s) {
  const int M = cfg_.records_per_cycle;
  const long cycle = static_cast<long>(s.step / static_cast<std::uint64_t>(M));
  const int phase = static_cast<int>(s.step % static_cast<std::uint64_t>(M));
  // Only a record that extends a cycle in phase order is measured (the surface is the cost).
  const bool next = cycles_.empty() || cycles_.back().index != cycle
                        ? phase == 0
                        : phase == cycles_.back().filled;
  if (!next) return;
  record(cycle, phase, layerSurface(s, cfg_.width, cfg_.diameter, cfg_.periodic_x, cfg_.surface));
}

void SurfaceRecorder::record(long cycle, int phase, const LayerSurface& surf) {
  const int M = cfg_.records_per_cycle;
  if (cycle < 0 || phase < 0 || phase >= M)
    throw std::invalid_argument("surface recorder: record " + std::to_string(phase) + " of cycle " +
                                std::to_string(cycle) + " is outside 0.." + std::to_string(M - 1) +
                                " of a cycle >= 0");
  if (surf.profile.height.size() != static_cast<std::size_t>(columns_))
    throw std::invalid_argument("surface recorder: a surface of " +
                                std::to_string(surf.profile.height.size()) + " columns, not " +
                                std::to_string(columns_));
  if (cycles_.empty() || cycles_.back().index != cycle) {
    // A cycle whose first record was missed (a run started mid-cycle) is never whole.
    if (phase != 0) return;
    Cycle c;
    c.index = cycle;
    c.height.assign(static_cast<std::size_t>(M) * columns_, 0.0);
    c.bulk.assign(static_cast<std::size_t>(M), 0.0);
    cycles_.push_back(std::move(c));
    while (static_cast<int>(cycles_.size()) > cfg_.keep_cycles + 1) cycles_.pop_front();
  }
  Cycle& c = cycles_.back();
  if (phase != c.filled) return;  // a gap: the cycle stays partial
  std::copy(surf.profile.height.begin(), surf.profile.height.end(),
            c.height.begin() + static_cast<long>(phase) * columns_);
  c.bulk[phase] = surf.bulk_area_fraction;
  ++c.filled;
}

SurfaceSeries SurfaceRecorder::series(long from) const {
  SurfaceSeries s;
  s.columns = columns_;
  s.records_per_cycle = cfg_.records_per_cycle;
  s.column_width = cfg_.width / columns_;
  s.diameter = cfg_.diameter;
  s.periodic_x = cfg_.periodic_x;
  // The longest run of consecutive whole cycles at the end, from `from` on.
  std::vector<const Cycle*> kept;
  for (const Cycle& c : cycles_) {
    if (c.index < from || c.filled != cfg_.records_per_cycle) continue;
    // A partial cycle in between breaks the run: the next whole one is not consecutive.
    if (!kept.empty() && c.index != kept.back()->index + 1) kept.clear();
    kept.push_back(&c);
  }
  while (static_cast<int>(kept.size()) > cfg_.keep_cycles) kept.erase(kept.begin());
  s.cycles = static_cast<int>(kept.size());
  s.first_cycle = kept.empty() ? from : kept.front()->index;
  for (const Cycle* c : kept) {
    s.height.insert(s.height.end(), c->height.begin(), c->height.end());
    s.bulk_area_fraction.insert(s.bulk_area_fraction.end(), c->bulk.begin(), c->bulk.end());
  }
  return s;
}

void SurfaceRecorder::saveState(h5::File& file, const std::string& group) const {
  file.createGroup(group);
  std::vector<double> height, bulk;
  std::vector<std::int64_t> index, filled;
  for (const Cycle& c : cycles_) {
    height.insert(height.end(), c.height.begin(), c.height.end());
    bulk.insert(bulk.end(), c.bulk.begin(), c.bulk.end());
    index.push_back(c.index);
    filled.push_back(c.filled);
  }
  file.writeDataset(group + "/height", height, {height.size()});
  file.writeDataset(group + "/bulk_area_fraction", bulk, {bulk.size()});
  file.writeDataset(group + "/cycle_index", index, {index.size()});
  file.writeDataset(group + "/cycle_filled", filled, {filled.size()});
}

void SurfaceRecorder::restoreState(const h5::File& file, const std::string& group) {
  const auto height = file.readDataset<double>(group + "/height");
  const auto bulk = file.readDataset<double>(group + "/bulk_area_fraction");
  const auto index = file.readDataset<std::int64_t>(group + "/cycle_index");
  const auto filled = file.readDataset<std::int64_t>(group + "/cycle_filled");
  const std::size_t M = static_cast<std::size_t>(cfg_.records_per_cycle);
  const std::size_t per = M * static_cast<std::size_t>(columns_);
  if (filled.size() != index.size() || height.size() != index.size() * per ||
      bulk.size() != index.size() * M)
    throw h5::H5Error(file.name() + ": " + group + " does not fit this run's surface recorder");
  cycles_.clear();
  for (std::size_t k = 0; k < index.size(); ++k) {
    Cycle c;
    c.index = static_cast<long>(index[k]);
    c.filled = static_cast<int>(filled[k]);
    c.height.assign(height.begin() + static_cast<long>(k * per),
                    height.begin() + static_cast<long>((k + 1) * per));
    c.bulk.assign(bulk.begin() + static_cast<long>(k * M),
                  bulk.begin() + static_cast<long>((k + 1) * M));
    cycles_.push_back(std::move(c));
  }
}

}  // namespace granwave
