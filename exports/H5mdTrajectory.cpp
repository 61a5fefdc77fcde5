#include "exports/H5mdTrajectory.hpp"

#include <cstdint>
#include <cstdlib>
#include <span>
#include <vector>

#include "h5/File.hpp"

namespace granwave {

namespace {

constexpr double kNm = kH5mdExportNanometresPerMetre;
const std::string kGroup = "/particles/trajectory";

// One H5MD time-dependent element, <group>/{step,time,value}, a frame per row.
struct Series {
  h5::ExtendibleDataset<std::int64_t> step;
  h5::ExtendibleDataset<double> time;
  h5::ExtendibleDataset<double> value;

  void append(const Snapshot& s, std::span<const double> row) {
    const std::int64_t k[] = {static_cast<std::int64_t>(s.step)};
    const double t[] = {s.time};
    step.append(k);
    time.append(t);
    value.append(row);
  }
  void close() {
    step.close();
    time.close();
    value.close();
  }
};

Series createSeries(h5::File& f, const std::string& group, const h5::Shape& row,
                    const std::string& unit) {
  f.createGroup(group);
  Series s{f.createExtendible<std::int64_t>(group + "/step", {}, 256),
           f.createExtendible<double>(group + "/time", {}, 256),
           f.createExtendible<double>(group + "/value", row, 1)};
  f.writeStringAttribute(group + "/time", "unit", "s");
  f.writeStringAttribute(group + "/value", "unit", unit);
  return s;
}

std::string authorName(const std::string& author) {
  if (!author.empty()) return author;
  const char* user = std::getenv("USER");
  return user != nullptr && user[0] != '\0' ? user : "unknown";
}

class H5mdTrajectoryWriter final : public TrajectoryWriter {
 public:
  H5mdTrajectoryWriter(const std::string& path, const std::string& target, TrajectoryHeader h)
      : file_(h5::File::create(path, target)), h_(std::move(h)) {
    file_.createGroup("/h5md/author");
    file_.writeArrayAttribute<std::int64_t>("/h5md", "version", {1, 1});
    file_.writeStringAttribute("/h5md/author", "name", authorName(h_.author));
    file_.createGroup("/h5md/creator");
    file_.writeStringAttribute("/h5md/creator", "name", "granwave");
    file_.writeStringAttribute("/h5md/creator", "version", h_.version);
    file_.createGroup("/h5md/modules/units");
    file_.writeArrayAttribute<std::int64_t>("/h5md/modules/units", "version", {1, 0});
    file_.writeStringAttribute("/h5md/modules/units", "system", "SI");
    file_.createGroup(kGroup + "/box");
    file_.writeAttribute<std::int64_t>(kGroup + "/box", "dimension", 3);
    file_.writeStringArrayAttribute(
        kGroup + "/box", "boundary",
        {h_.box.periodic_x ? "periodic" : "none", "none", h_.box.periodic_z ? "periodic" : "none"});
  }

  void write(const Snapshot& s) override {
    const std::size_t n = static_cast<std::size_t>(s.size());
    if (!position_.value.isOpen()) create(n);
    const BoxInfo& b = h_.box;
    const double edges[] = {b.width * kNm, 0, 0, 0, b.thickness * kNm, 0, 0, 0, b.height * kNm};
    edges_.append(s, edges);
    row_.assign(3 * n, 0.0);
    for (std::size_t i = 0; i < n; ++i) row_[3 * i] = s.x[i] * kNm, row_[3 * i + 2] = s.z[i] * kNm;
    position_.append(s, row_);
    for (std::size_t i = 0; i < n; ++i) row_[3 * i] = s.vx[i], row_[3 * i + 2] = s.vz[i];
    velocity_.append(s, row_);
    row_.assign(3 * n, 0.0);
    for (std::size_t i = 0; i < n; ++i) row_[3 * i + 1] = s.omega[i];
    angular_velocity_.append(s, row_);
    const double plate[] = {s.plate_height * kNm};
    plate_height_.append(s, plate);
  }

  void close() override {
    for (Series* series : {&edges_, &position_, &velocity_, &angular_velocity_, &plate_height_})
      series->close();
    file_.close();
  }

 private:
  void create(std::size_t n) {
    edges_ = createSeries(file_, kGroup + "/box/edges", {3, 3}, "nm");
    position_ = createSeries(file_, kGroup + "/position", {n, 3}, "nm");
    velocity_ = createSeries(file_, kGroup + "/velocity", {n, 3}, "m s-1");
    angular_velocity_ = createSeries(file_, kGroup + "/angular_velocity", {n, 3}, "rad s-1");
    plate_height_ = createSeries(file_, "/observables/plate_height", {}, "nm");
  }

  h5::File file_;
  TrajectoryHeader h_;
  Series edges_, position_, velocity_, angular_velocity_, plate_height_;
  std::vector<double> row_;
};

}  // namespace

std::unique_ptr<TrajectoryWriter> makeH5mdWriter(const std::string& path, const std::string& target,
                                                 const TrajectoryHeader& header) {
  return std::make_unique<H5mdTrajectoryWriter>(path, target, header);
}

}  // namespace granwave
