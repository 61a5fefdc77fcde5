#pragma once
// The 2D continuum beside the particles ([continuum] of the surface-waves study;
// docs/studies.md). Each continuum run's surface is measured by the particles' rule
// (studies/hydro_run/ContinuumSurface.hpp) and its spectrum taken over the run's second half,
// so the two models' waves are one measure on two models; a point's runs are combined over the
// continuum's seeds as the particles' are over theirs. Accuracy: the continuum's wavelength
// over the particles' at the same drive, box and rows, and the onset of each over the same
// Gamma. Cost: each model's CPU seconds per drive cycle (user + sys of its runs), so the width
// from which the continuum is the cheaper model is read off the widths of [continuum].
#include <vector>

#include "studies/surface_waves/SurfaceWavesAnalysis.hpp"

namespace granwave {

// One entry per continuum point (variant, width, Gamma), in the order of continuumPoints().
// `particle_runs`: every particle run read so far (those of continuumParticlePoints() among
// them).
std::vector<ContinuumWavePair> continuumBesideParticles(
    const SurfaceWavesConfig& config, const RunSet& runs,
    const std::vector<SurfaceWaveRun>& particle_runs);

// Per variant and width: the continuum's onset over [continuum] gammas, and the particles'
// over the same Gamma (so the two are bracketed alike), in that order for each.
std::vector<SurfaceWaveOnset> continuumOnsets(const SurfaceWavesConfig& config,
                                              const std::vector<ContinuumWavePair>& pairs);

}  // namespace granwave
