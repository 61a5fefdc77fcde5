#include "studies/cli/ExportCommand.hpp"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <filesystem>

#include "exports/TrajectoryWriter.hpp"
#include "files/AtomicOutput.hpp"
#include "files/OutputPath.hpp"
#include "particles/H5mdReader.hpp"
#include "scene/SceneDerived.hpp"
#include "scene/SceneParser.hpp"
#include "studies/cli/OptionChecks.hpp"
#include "studies/cli/Version.hpp"

namespace granwave {

namespace {

const TrajectoryFormatInfo* formatNamed(const std::string& name) {
  for (const TrajectoryFormatInfo& f : trajectoryFormats())
    if (f.name == name) return &f;
  return nullptr;
}

const TrajectoryFormatInfo* formatOfExtension(const std::string& path) {
  const std::string extension = std::filesystem::path(path).extension().string();
  for (const TrajectoryFormatInfo& f : trajectoryFormats())
    if (f.extension == extension) return &f;
  return nullptr;
}

// --format if given, else the one the output's extension names, else extended XYZ. A
// --format that contradicts a known extension is refused: the file would lie about itself.
const TrajectoryFormatInfo& chosenFormat(const ExportOptions& opt) {
  const TrajectoryFormatInfo* by_extension = formatOfExtension(opt.output);
  if (opt.format.empty()) return by_extension ? *by_extension : trajectoryFormats().front();
  const TrajectoryFormatInfo& named = *formatNamed(opt.format);  // CLI11 checked the name
  if (by_extension && by_extension != &named)
    throw files::PathError(fmt::format(
        "{}: the extension {} is that of --format {}, not of --format {}; name the output {}",
        opt.output, by_extension->extension, by_extension->name, named.name,
        std::filesystem::path(opt.output).replace_extension(named.extension).string()));
  return named;
}

std::string formatList() {
  std::string list;
  for (const TrajectoryFormatInfo& f : trajectoryFormats())
    list += fmt::format("{}{} ({}, {})", list.empty() ? "" : ", ", f.name, f.extension, f.label);
  return list;
}

}  // namespace

void addExportCommand(CLI::App& app, ExportOptions& opt) {
  CLI::App* cmd = app.add_subcommand(
      "export", "Write a run's trajectory for other tools (ASE, OVITO, MDAnalysis, HOOMD, LAMMPS)");
  cmd->add_option("run", opt.run_path, "Run file (H5MD, from granwave simulate)")
      ->required()
      ->check(regularInputFile());
  cmd->add_option("-o,--output", opt.output,
                  "Output file (default: the run file's stem with the format's extension)");
  std::vector<std::string> names;
  for (const TrajectoryFormatInfo& f : trajectoryFormats()) names.emplace_back(f.name);
  cmd->add_option("--format", opt.format,
                  "Output format: " + formatList() +
                      " (default: the one the output's extension names, else extxyz)")
      ->check(CLI::IsMember(names));
  cmd->add_option("--every", opt.every, "Write every K-th frame")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
}

int runExport(const ExportOptions& opt) {
  const TrajectoryFormatInfo& format = chosenFormat(opt);
  const H5mdReader run(opt.run_path);
  std::string out = opt.output;
  if (out.empty())
    out = std::filesystem::path(opt.run_path).replace_extension(format.extension).string();
  files::requireDistinct({{"run file", opt.run_path}}, {{"export", out}});
  const Scene scene = parseSceneString(run.sceneToml(), {}, opt.run_path + ": /parameters/scene");
  const TrajectoryHeader header{run.box(), scene.particles.diameter, derive(scene).mass, kVersion,
                                run.provenance().author};
  // Atomically: written beside the output, renamed over it when complete.
  files::AtomicOutput file(out);
  const std::unique_ptr<TrajectoryWriter> writer =
      makeTrajectoryWriter(format.format, file.temporaryPath(), out, header);
  const auto every = static_cast<std::size_t>(opt.every);
  for (std::size_t i = 0; i < run.frameCount(); i += every) writer->write(run.frame(i));
  writer->close();
  file.commit();
  fmt::print("run             {}\n", opt.run_path);
  fmt::print("frames          {} of {} (every {})\n", (run.frameCount() + every - 1) / every,
             run.frameCount(), opt.every);
  fmt::print("output          {} ({})\n", out, format.label);
  return 0;
}

}  // namespace granwave
