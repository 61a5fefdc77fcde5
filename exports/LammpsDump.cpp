#include "exports/LammpsDump.hpp"

#include <fmt/format.h>

#include "exports/ExportStream.hpp"

namespace granwave {

namespace {

class LammpsDumpWriter final : public TrajectoryWriter {
 public:
  LammpsDumpWriter(const std::string& path, const std::string& target, TrajectoryHeader header)
      : stream_(path, target, false), h_(std::move(header)) {}

  void write(const Snapshot& s) override {
    std::ofstream& out = stream_.out();
    const BoxInfo& box = h_.box;
    out << fmt::format("ITEM: TIMESTEP\n{}\nITEM: NUMBER OF ATOMS\n{}\n", s.step, s.size());
    out << fmt::format("ITEM: BOX BOUNDS {} ff {}\n", box.periodic_x ? "pp" : "ff",
                       box.periodic_z ? "pp" : "ff");
    out << fmt::format("0 {}\n{} {}\n{} {}\n", box.width, -0.5 * box.thickness, 0.5 * box.thickness,
                       s.plate_height, s.plate_height + box.height);
    out << "ITEM: ATOMS id type mass radius x y z vx vy vz omegax omegay omegaz\n";
    const double radius = 0.5 * h_.diameter;
    for (int i = 0; i < s.size(); ++i)
      out << fmt::format("{} 1 {} {} {} 0 {} {} 0 {} 0 {} 0\n", i + 1, h_.mass, radius, s.x[i],
                         s.z[i], s.vx[i], s.vz[i], s.omega[i]);
    stream_.check();
  }

  void close() override { stream_.close(); }

 private:
  ExportStream stream_;
  TrajectoryHeader h_;
};

}  // namespace

std::unique_ptr<TrajectoryWriter> makeLammpsDumpWriter(const std::string& path,
                                                       const std::string& target,
                                                       const TrajectoryHeader& header) {
  return std::make_unique<LammpsDumpWriter>(path, target, header);
}

}  // namespace granwave
