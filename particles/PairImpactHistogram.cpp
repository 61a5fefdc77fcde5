#include "particles/PairImpactHistogram.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "h5/H5Error.hpp"

namespace granwave {

PairImpactHistogram::PairImpactHistogram(const PairImpactBins& bins) : bins_(bins) {
  if (!(bins.speed_max > 0) || bins.speed_bins < 1 || bins.phase_bins < 1 || !(bins.period >= 0))
    throw std::invalid_argument(
        "pair impact histogram: speed_max > 0, speed_bins >= 1, phase_bins >= 1 and period >= 0 "
        "expected");
  counts_.assign(static_cast<std::size_t>(bins.phase_bins) * bins.speed_bins, 0);
}

void PairImpactHistogram::pairImpact(const PairImpact& im) {
  if (im.time < bins_.start_time || im.time >= bins_.end_time || im.height < bins_.z_min ||
      im.height > bins_.z_max)
    return;
  int phase = 0;
  if (bins_.period > 0) {
    const double x = im.time / bins_.period;
    phase = static_cast<int>((x - std::floor(x)) * bins_.phase_bins);
    if (phase >= bins_.phase_bins) phase = bins_.phase_bins - 1;  // round-off at x -> 1
  }
  int k = static_cast<int>(im.normal_speed / bins_.speed_max * bins_.speed_bins);
  if (k >= bins_.speed_bins) k = bins_.speed_bins - 1;
  if (k < 0) k = 0;
  ++counts_[static_cast<std::size_t>(phase) * bins_.speed_bins + k];
  ++total_;
}

std::vector<std::uint64_t> PairImpactHistogram::speedCounts(const std::vector<bool>& use) const {
  std::vector<std::uint64_t> sum(static_cast<std::size_t>(bins_.speed_bins), 0);
  for (int p = 0; p < bins_.phase_bins; ++p) {
    if (!use.empty() && !use[p]) continue;
    for (int k = 0; k < bins_.speed_bins; ++k) sum[k] += count(p, k);
  }
  return sum;
}

double PairImpactHistogram::weightedMean(const std::function<double(double)>& f,
                                         const std::vector<bool>& use) const {
  const std::vector<std::uint64_t> c = speedCounts(use);
  double sum = 0, n = 0;
  for (int k = 0; k < bins_.speed_bins; ++k) {
    if (c[k] == 0) continue;
    sum += static_cast<double>(c[k]) * f(speedBinCentre(k));
    n += static_cast<double>(c[k]);
  }
  return n > 0 ? sum / n : std::numeric_limits<double>::quiet_NaN();
}

namespace {

const char* const kRealBins[] = {"speed_max", "period", "start_time", "end_time", "z_min", "z_max"};
double* realBin(PairImpactBins& b, int i) {
  double* fields[] = {&b.speed_max, &b.period, &b.start_time, &b.end_time, &b.z_min, &b.z_max};
  return fields[i];
}

PairImpactBins readBins(const h5::File& file, const std::string& group) {
  PairImpactBins b;
  for (int i = 0; i < 6; ++i) *realBin(b, i) = file.readAttribute<double>(group, kRealBins[i]);
  b.speed_bins = static_cast<int>(file.readAttribute<std::int64_t>(group, "speed_bins"));
  b.phase_bins = static_cast<int>(file.readAttribute<std::int64_t>(group, "phase_bins"));
  return b;
}

}  // namespace

void PairImpactHistogram::saveState(h5::File& file, const std::string& group) const {
  file.createGroup(group);
  file.writeDataset(
      group + "/counts", counts_,
      {static_cast<std::size_t>(bins_.phase_bins), static_cast<std::size_t>(bins_.speed_bins)},
      h5::Storage::compressed);  // mostly empty bins
  file.writeStringAttribute(group + "/counts", "unit", "1");
  PairImpactBins b = bins_;
  for (int i = 0; i < 6; ++i) file.writeAttribute(group, kRealBins[i], *realBin(b, i));
  file.writeAttribute<std::int64_t>(group, "speed_bins", bins_.speed_bins);
  file.writeAttribute<std::int64_t>(group, "phase_bins", bins_.phase_bins);
  file.writeAttribute<std::uint64_t>(group, "total", total_);
}

void PairImpactHistogram::restoreState(const h5::File& file, const std::string& group) {
  PairImpactBins saved = readBins(file, group);
  saved.start_time = bins_.start_time;
  if (saved.speed_max != bins_.speed_max || saved.speed_bins != bins_.speed_bins ||
      saved.phase_bins != bins_.phase_bins || saved.period != bins_.period ||
      saved.end_time != bins_.end_time || saved.z_min != bins_.z_min || saved.z_max != bins_.z_max)
    throw h5::H5Error(file.name() + ": " + group + " holds a pair impact histogram of other bins");
  bins_.start_time = file.readAttribute<double>(group, "start_time");
  counts_ = file.readDataset<std::uint64_t>(
      group + "/counts",
      {static_cast<std::size_t>(bins_.phase_bins), static_cast<std::size_t>(bins_.speed_bins)});
  total_ = file.readAttribute<std::uint64_t>(group, "total");
}

PairImpactHistogram PairImpactHistogram::read(const h5::File& file, const std::string& group) {
  PairImpactBins b;
  try {
    b = readBins(file, group);
    PairImpactHistogram h(b);
    h.restoreState(file, group);
    return h;
  } catch (const std::invalid_argument& e) {
    throw h5::H5Error(file.name() + ": " + group + ": " + e.what());
  }
}

}  // namespace granwave
