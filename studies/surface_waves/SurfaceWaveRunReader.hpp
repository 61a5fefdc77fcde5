#pragma once
// What the surface-waves study reads from one finished run: the /surface group of its fields
// file, the stability detector's verdict, RMS(v_x) and the dissipation from its run file.
#include "studies/runner/RunRequest.hpp"
#include "studies/surface_waves/SurfaceWavesAnalysis.hpp"

namespace granwave {

SurfaceWaveRun readSurfaceWaveRun(const RunRecord& record, const SurfaceWavePoint& point);

}  // namespace granwave
