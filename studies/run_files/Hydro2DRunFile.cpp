#include "studies/run_files/Hydro2DRunFile.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>

#include "coarse_grain/FieldsFile.hpp"
#include "coarse_grain/SurfaceWavesFile.hpp"
#include "files/AtomicOutput.hpp"
#include "h5/AtomicFile.hpp"
#include "h5/File.hpp"

namespace granwave {

namespace {

void put(h5::File& f, const std::string& path, const std::vector<double>& v, const h5::Shape& s,
         const char* unit) {
  f.writeDataset(path, v, s);
  f.writeStringAttribute(path, "unit", unit);
}

void writePlateFrame(h5::File& f, const Hydro2DRunContent& c) {
  const std::size_t P = c.phases(), X = c.columns, N = c.cells;
  f.createGroup("/plate_frame");
  put(f, "/plate_frame/node_z", c.node_z, {P, X, N + 1}, "m");
  put(f, "/plate_frame/area_fraction", c.area_fraction, {P, X, N}, "1");
  put(f, "/plate_frame/temperature", c.temperature, {P, X, N}, "J");
  put(f, "/plate_frame/velocity_x", c.velocity_x, {P, X, N}, "m s-1");
  put(f, "/plate_frame/velocity_z", c.velocity_z, {P, X, N}, "m s-1");
  put(f, "/plate_frame/pressure", c.pressure, {P, X, N}, "N m-1");
  f.createGroup("/phases");
  put(f, "/phases/time", c.time, {P}, "s");
  put(f, "/phases/plate_height", c.plate_height, {P}, "m");
  put(f, "/phases/center_of_mass_height", c.center_of_mass_height, {P}, "m");
  f.createGroup("/run");
  put(f, "/run/center_of_mass_height", c.com_per_phase, {c.com_per_phase.size()}, "m");
}

void writeSolver(h5::File& f, const Hydro2DRunContent& c) {
  const std::string s = "/solver";
  f.createGroup(s);
  f.writeAttribute<std::int64_t>(s, "columns", static_cast<std::int64_t>(c.columns));
  f.writeAttribute<std::int64_t>(s, "cells", static_cast<std::int64_t>(c.cells));
  f.writeAttribute<double>(s, "width", c.width);
  f.writeAttribute<std::int64_t>(s, "periodic_x", c.periodic ? 1 : 0);
  f.writeAttribute<std::int64_t>(s, "samples_per_cycle", c.samples_per_cycle);
  f.writeAttribute<double>(s, "rtol", c.rtol);
  f.writeAttribute<std::int64_t>(s, "cycles", c.cycles);
  f.writeAttribute<double>(s, "cpu_seconds", c.cpu_seconds);
  f.writeAttribute<double>(s, "mass_drift", c.mass_drift);
  f.writeAttribute<std::int64_t>(s, "steps", c.steps);
  f.writeAttribute<std::int64_t>(s, "rhs_evals", c.rhs_evals);
  f.writeAttribute<std::int64_t>(s, "linear_iterations", c.linear_iterations);
  f.writeAttribute<std::int64_t>(s, "preconditioner_jacobians", c.preconditioner_jacobians);
  f.writeAttribute<std::int64_t>(s, "remaps", c.remaps);
  f.writeAttribute<double>(s, "remap_heat", c.remap_heat);
}

// Column i's left (side 0) and right (side 1) edge at node j: point (i (N + 1) + j) 2 + side.
std::size_t pointIndex(const Hydro2DRunContent& c, std::size_t i, std::size_t j, int side) {
  return (i * (c.cells + 1) + j) * 2 + side;
}

// The mesh ParaView reads (/xdmf): the quadrilaterals' corners once, and per phase the
// points (x, 0, z), lab frame, and the cell fields, velocity as (v_x, 0, v_z) in the lab frame.
void writeMesh(h5::File& f, const Hydro2DRunContent& c) {
  const std::size_t X = c.columns, N = c.cells, E = X * N, Np = 2 * X * (N + 1);
  f.createGroup("/xdmf");
  std::vector<std::int64_t> quads;
  for (std::size_t i = 0; i < X; ++i)
    for (std::size_t k = 0; k < N; ++k)
      for (auto [j, side] : {std::pair{k, 0}, {k, 1}, {k + 1, 1}, {k + 1, 0}})
        quads.push_back(static_cast<std::int64_t>(pointIndex(c, i, j, side)));
  f.writeDataset("/xdmf/quadrilaterals", quads, {E, 4});
  const double dx = c.width / static_cast<double>(X);
  for (std::size_t p = 0; p < c.phases(); ++p) {
    const std::string grp = fmt::format("/xdmf/p{:04d}", p);
    f.createGroup(grp);
    std::vector<double> points(3 * Np, 0.0), velocity(3 * E, 0.0);
    for (std::size_t i = 0; i < X; ++i)
      for (std::size_t j = 0; j <= N; ++j)
        for (int side : {0, 1}) {
          const std::size_t q = pointIndex(c, i, j, side);
          points[3 * q] = (static_cast<double>(i) + side) * dx;
          points[3 * q + 2] = c.node_z[(p * X + i) * (N + 1) + j] + c.plate_height[p];
        }
    const auto first = static_cast<long>(p * E);
    for (std::size_t e = 0; e < E; ++e) {
      velocity[3 * e] = c.velocity_x[p * E + e];
      velocity[3 * e + 2] = c.velocity_z[p * E + e] + c.plate_velocity[p];
    }
    put(f, grp + "/points", points, {Np, 3}, "m");
    put(f, grp + "/area_fraction",
        {c.area_fraction.begin() + first, c.area_fraction.begin() + first + static_cast<long>(E)},
        {E}, "1");
    put(f, grp + "/temperature",
        {c.temperature.begin() + first, c.temperature.begin() + first + static_cast<long>(E)}, {E},
        "J");
    put(f, grp + "/velocity", velocity, {E, 3}, "m s-1");
  }
}

std::string xdmfText(const std::string& h5_name, const Hydro2DRunContent& c) {
  const std::size_t E = c.columns * c.cells, Np = 2 * c.columns * (c.cells + 1);
  auto item = [&](const std::string& dims, const char* type, const std::string& path) {
    return fmt::format(
        "<DataItem Dimensions=\"{}\" NumberType=\"{}\" Precision=\"8\" Format=\"HDF\">{}:{}"
        "</DataItem>\n",
        dims, type, h5_name, path);
  };
  std::string s = "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n<Domain>\n";
  s += "<Grid Name=\"phases\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (std::size_t p = 0; p < c.phases(); ++p) {
    const std::string grp = fmt::format("/xdmf/p{:04d}", p);
    s += fmt::format("<Grid Name=\"p{:04d}\" GridType=\"Uniform\">\n", p);
    s += fmt::format("<Time Value=\"{:.9g}\"/>\n", c.time[p]);
    s += fmt::format("<Topology TopologyType=\"Quadrilateral\" NumberOfElements=\"{}\">\n", E);
    s += item(fmt::format("{} 4", E), "Int", "/xdmf/quadrilaterals") + "</Topology>\n";
    s += "<Geometry GeometryType=\"XYZ\">\n";
    s += item(fmt::format("{} 3", Np), "Float", grp + "/points") + "</Geometry>\n";
    for (const char* name : {"area_fraction", "temperature"}) {
      s += fmt::format("<Attribute Name=\"{}\" AttributeType=\"Scalar\" Center=\"Cell\">\n", name);
      s += item(fmt::format("{}", E), "Float", grp + "/" + name) + "</Attribute>\n";
    }
    s += "<Attribute Name=\"velocity\" AttributeType=\"Vector\" Center=\"Cell\">\n";
    s += item(fmt::format("{} 3", E), "Float", grp + "/velocity") + "</Attribute>\n";
    s += "</Grid>\n";
  }
  return s + "</Grid>\n</Domain>\n</Xdmf>\n";
}

void writeXdmf(const std::string& xdmf_path, const std::string& h5_name,
               const Hydro2DRunContent& c) {
  files::AtomicOutput out(xdmf_path);
  {
    std::ofstream os(out.temporaryPath(), std::ios::trunc);
    os << xdmfText(h5_name, c);
    os.flush();
    if (!os)
      throw std::system_error(errno ? errno : EIO, std::generic_category(),
                              xdmf_path + ": cannot write the XDMF sidecar");
  }
  out.commit();
}

}  // namespace

Hydro2DSolverRecord readHydro2DSolver(const std::string& path) {
  const h5::File f = h5::File::openReadOnly(path);
  if (!f.hasAttribute("/", "format") || f.readStringAttribute("/", "format") != kHydro2DRunFormat)
    throw std::runtime_error(path + ": not a 2D hydro run file (format " + kHydro2DRunFormat + ")");
  const std::string s = "/solver";
  Hydro2DSolverRecord r;
  r.cycles = f.readAttribute<std::int64_t>(s, "cycles");
  r.steps = f.readAttribute<std::int64_t>(s, "steps");
  r.rhs_evals = f.readAttribute<std::int64_t>(s, "rhs_evals");
  r.remaps = f.readAttribute<std::int64_t>(s, "remaps");
  r.cpu_seconds = f.readAttribute<double>(s, "cpu_seconds");
  r.mass_drift = f.readAttribute<double>(s, "mass_drift");
  return r;
}

void writeHydro2DRunFile(const std::string& path, const Hydro2DRunContent& c) {
  h5::AtomicFile af(path);
  h5::File& f = af.file();
  f.writeStringAttribute("/", "format", kHydro2DRunFormat);
  writePlateFrame(f, c);
  writeMesh(f, c);
  writeSolver(f, c);
  writeSurfaceWaves(f, c.surface);  // nothing when the run had too few cycles for a window
  writeEnergyBudget(f, c.budget);   // nothing unless the scene asked for it
  f.createGroup("/parameters");
  f.writeStringDataset("/parameters/scene", c.scene_toml);
  af.commit();
  try {  // the pair or neither
    writeXdmf(xdmfSidecarPath(path), std::filesystem::path(path).filename().string(), c);
  } catch (...) {
    std::remove(path.c_str());
    throw;
  }
}

}  // namespace granwave
