#pragma once
// Writes the fields file (HDF5; layout in FieldsLayout.hpp, docs/fields.md) and its XDMF
// sidecar for ParaView; FieldsReader.hpp reads it back. Written atomically; the sidecar
// FIELDS.xdmf after the file.
#include <string>

#include "coarse_grain/FieldsAnalysis.hpp"
#include "coarse_grain/PhaseProfiles.hpp"
#include "h5/File.hpp"

namespace granwave {

// The x-z cells (/fields, /xdmf and the XDMF sidecar) are for viewers: the studies read the
// profiles, phases, fronts and states only, and leave the cells out of the runs they cache
// (nine tenths of a fields file at 400 phases per cycle).
enum class FieldsCells { written, left_out };

void writeFieldsFile(const std::string& path, const FieldsAnalysis& analysis,
                     FieldsCells cells = FieldsCells::written);
// Path of the XDMF sidecar for a fields file (same name, .xdmf).
std::string xdmfSidecarPath(const std::string& fields_path);

// The profiles, per-phase series and fronts of a window under `root` ("" or a state's root;
// the rows' heights are /grid/z). Blocks and profiles that are empty are left out: the
// continuum has no blocks and no RMS(v_x). The hydro run file stores its lab frame with it.
void writePhaseProfiles(h5::File& file, const std::string& root, const PhaseProfiles& profiles);

}  // namespace granwave
