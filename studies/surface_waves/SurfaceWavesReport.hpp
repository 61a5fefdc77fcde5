#pragma once
// The surface-waves study's report: onset, spectra, box modes against Faraday waves, the
// dispersion relation against published granular Faraday waves, the dissipation axis and
// r_x beside the spectrum. Figures, tables and prose only.
#include "studies/report/Report.hpp"
#include "studies/surface_waves/SurfaceWavesAnalysis.hpp"

namespace granwave {

void reportSurfaceWaves(const SurfaceWavesConfig& config, const SurfaceWavesResults& results,
                        Report& report);

// The parts of the report (SurfaceWavesFigures.cpp): spectra of the example runs, the
// dispersion figure and table, the width-scan table.
void addSpectra(const SurfaceWavesResults& results, ReportSection& section);
void addDispersion(const SurfaceWavesConfig& config, const SurfaceWavesResults& results,
                   ReportSection& section);
void addWidthScan(const SurfaceWavesConfig& config, const SurfaceWavesResults& results,
                  ReportSection& section);

// The 2D continuum beside the particles ([continuum]; SurfaceWavesContinuumReport.cpp): a
// section of its own, none without continuum points.
void addContinuum(const SurfaceWavesConfig& config, const SurfaceWavesResults& results,
                  Report& report);

// "ED dry W=120 periodic rows=10 f=10 Gamma=4" style name of a point (no seed).
std::string pointName(const SurfaceWavesConfig& config, const SurfaceWavePoint& point);

}  // namespace granwave
