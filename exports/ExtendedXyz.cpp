#include "exports/ExtendedXyz.hpp"

#include <fmt/format.h>

#include "exports/ExportStream.hpp"

namespace granwave {

namespace {

class ExtendedXyzWriter final : public TrajectoryWriter {
 public:
  ExtendedXyzWriter(const std::string& path, const std::string& target, TrajectoryHeader header)
      : stream_(path, target, false), h_(std::move(header)) {}

  void write(const Snapshot& s) override {
    std::ofstream& out = stream_.out();
    const BoxInfo& box = h_.box;
    out << s.size() << '\n';
    out << fmt::format(
        "Lattice=\"{} 0 0 0 {} 0 0 0 {}\" Properties=species:S:1:pos:R:3:"
        "velocities:R:3:angular_velocity:R:3:radius:R:1 Time={} step={} "
        "plate_height={} units=SI pbc=\"{} F {}\"\n",
        box.width, box.thickness, box.height, s.time, s.step, s.plate_height,
        box.periodic_x ? 'T' : 'F', box.periodic_z ? 'T' : 'F');
    const double radius = 0.5 * h_.diameter;
    for (int i = 0; i < s.size(); ++i)
      out << fmt::format("X {} 0 {} {} 0 {} 0 {} 0 {}\n", s.x[i], s.z[i], s.vx[i], s.vz[i],
                         s.omega[i], radius);
    stream_.check();
  }

  void close() override { stream_.close(); }

 private:
  ExportStream stream_;
  TrajectoryHeader h_;
};

}  // namespace

std::unique_ptr<TrajectoryWriter> makeExtendedXyzWriter(const std::string& path,
                                                        const std::string& target,
                                                        const TrajectoryHeader& header) {
  return std::make_unique<ExtendedXyzWriter>(path, target, header);
}

}  // namespace granwave
