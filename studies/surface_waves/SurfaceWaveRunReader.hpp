#pragma once
// What the surface-waves study reads from one finished run: the /surface group of its fields
// file, the stability detector's verdict, RMS(v_x) and the dissipation from its run file; of a
// 2D continuum run, the /surface group of its hydro run file.
#include "studies/runner/RunRequest.hpp"
#include "studies/surface_waves/SurfaceWavesAnalysis.hpp"

namespace granwave {

SurfaceWaveRun readSurfaceWaveRun(const RunRecord& record, const SurfaceWavePoint& point);

// A 2D continuum run ([continuum]): the /surface group of its hydro run file, measured by the
// particles' rule; no detector, RMS(v_x) or dissipation.
SurfaceWaveRun readContinuumWaveRun(const RunRecord& record, const SurfaceWavePoint& point);

}  // namespace granwave
