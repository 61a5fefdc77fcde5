#include "studies/cli/ExportCommand.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cerrno>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>

#include "files/OutputPath.hpp"
#include "particles/H5mdReader.hpp"
#include "studies/cli/OptionChecks.hpp"

namespace granwave {

namespace {

// One frame of extended XYZ (the format of ASE, ase.io.extxyz, also read by OVITO): the count,
// a comment line of key=value pairs (the cell as Lattice, the time, the units), then one line
// per disk. SI units throughout, as in the run file; the disks move in the x-z plane and spin
// about y. The shortest decimal that reads back to the same double, so the numbers are the run
// file's.
void writeFrame(std::ostream& out, const Snapshot& s, const BoxInfo& box, double radius) {
  out << s.size() << '\n';
  out << fmt::format(
      "Lattice=\"{} 0 0 0 {} 0 0 0 {}\" Properties=species:S:1:pos:R:3:"
      "velocities:R:3:angular_velocity:R:3:radius:R:1 Time={} step={} "
      "plate_height={} units=SI pbc=\"{} F {}\"\n",
      box.width, box.thickness, box.height, s.time, s.step, s.plate_height,
      box.periodic_x ? 'T' : 'F', box.periodic_z ? 'T' : 'F');
  for (int i = 0; i < s.size(); ++i)
    out << fmt::format("X {} 0 {} {} 0 {} 0 {} 0 {}\n", s.x[i], s.z[i], s.vx[i], s.vz[i],
                       s.omega[i], radius);
}

}  // namespace

void addExportCommand(CLI::App& app, ExportOptions& opt) {
  CLI::App* cmd = app.add_subcommand(
      "export", "Write a run's trajectory for other tools (extended XYZ: ASE, OVITO)");
  cmd->add_option("run", opt.run_path, "Run file (H5MD, from granwave simulate)")
      ->required()
      ->check(regularInputFile());
  cmd->add_option("-o,--output", opt.output, "Output file; default <run>.extxyz");
  cmd->add_option("--format", opt.format, "Output format")
      ->check(CLI::IsMember({"extxyz"}))
      ->capture_default_str();
  cmd->add_option("--every", opt.every, "Write every K-th frame")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
}

int runExport(const ExportOptions& opt) {
  const H5mdReader run(opt.run_path);
  std::string out = opt.output;
  if (out.empty())
    out = (std::filesystem::path(opt.run_path).replace_extension(".extxyz")).string();
  files::requireDistinct({{"run file", opt.run_path}}, {{"export", out}});
  std::error_code ec;
  const double radius = 0.5 * run.box().thickness;  // the box is one diameter thick
  // Atomically: a temporary beside the output, renamed when complete.
  const std::string tmp = files::temporaryFor(out);
  {
    std::ofstream file(tmp, std::ios::trunc);
    for (std::size_t i = 0; i < run.frameCount(); i += static_cast<std::size_t>(opt.every))
      writeFrame(file, run.frame(i), run.box(), radius);
    file.flush();
    if (!file) {
      std::filesystem::remove(tmp, ec);
      throw std::system_error(errno ? errno : EIO, std::generic_category(),
                              out + ": cannot write the export");
    }
  }
  std::filesystem::rename(tmp, out);
  fmt::print("run             {}\n", opt.run_path);
  fmt::print("frames          {} of {} (every {})\n",
             (run.frameCount() + opt.every - 1) / static_cast<std::size_t>(opt.every),
             run.frameCount(), opt.every);
  fmt::print("output          {} (extended XYZ, SI units)\n", out);
  return 0;
}

}  // namespace granwave
