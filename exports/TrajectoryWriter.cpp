#include "exports/TrajectoryWriter.hpp"

#include <stdexcept>

#include "exports/ExtendedXyz.hpp"
#include "exports/GsdTrajectory.hpp"
#include "exports/H5mdTrajectory.hpp"
#include "exports/LammpsDump.hpp"

namespace granwave {

const std::vector<TrajectoryFormatInfo>& trajectoryFormats() {
  static const std::vector<TrajectoryFormatInfo> formats{
      {TrajectoryFormat::ExtendedXyz, "extxyz", ".extxyz", "extended XYZ, SI units"},
      {TrajectoryFormat::Gsd, "gsd", ".gsd", "GSD, hoomd schema, SI units"},
      {TrajectoryFormat::LammpsDump, "lammps-dump", ".lammpstrj", "LAMMPS dump, units si"},
      {TrajectoryFormat::H5md, "h5md", ".h5md", "H5MD for MDAnalysis, lengths in nm"},
  };
  return formats;
}

const TrajectoryFormatInfo& trajectoryFormat(TrajectoryFormat format) {
  for (const TrajectoryFormatInfo& f : trajectoryFormats())
    if (f.format == format) return f;
  throw std::logic_error("trajectory format without an entry in trajectoryFormats()");
}

std::unique_ptr<TrajectoryWriter> makeTrajectoryWriter(TrajectoryFormat format,
                                                       const std::string& path,
                                                       const std::string& target,
                                                       const TrajectoryHeader& header) {
  switch (format) {
    case TrajectoryFormat::ExtendedXyz:
      return makeExtendedXyzWriter(path, target, header);
    case TrajectoryFormat::Gsd:
      return makeGsdWriter(path, target, header);
    case TrajectoryFormat::LammpsDump:
      return makeLammpsDumpWriter(path, target, header);
    case TrajectoryFormat::H5md:
      return makeH5mdWriter(path, target, header);
  }
  throw std::logic_error("unknown trajectory format");
}

}  // namespace granwave
