#pragma once
// The onset of surface waves and the dissipation axis of the surface-waves study.
//
// Onset: for each variant and frequency of the base box, Gamma_c is where the point first waves
// (SurfaceWaveSummary::waves: half its windows pooled over seeds, counted, hold an f/2 standing
// wave), where the share of such windows rises through 1/2, linear between the two Gamma that
// bracket it. Its error propagates the binomial
// error of the two shares, sqrt(w (1 - w) / n) with n the windows at each point (windows of 10
// cycles treated as independent), through the interpolation, and adds the bracket's width /
// sqrt(12) when one share is exactly 0 or 1 (the crossing is then only known to lie in the
// bracket). Without a crossing Gamma_c lies below the first or above the last Gamma.
//
// Dissipation: each variant's effective restitution of the pair impacts and its energy lost
// per cycle over its mean kinetic energy, at [dissipation] gamma and the first frequency, beside
// its Gamma_c there; the rank correlation (Spearman) of Gamma_c with e_eff over the variants
// that have an onset tells whether the onset follows the layer's dissipation.
#include <vector>

#include "studies/surface_waves/SurfaceWavesAnalysis.hpp"

namespace granwave {

// The onset of one variant at frequency f in the box of width_d (periodic or between side walls)
// over `gammas` (in order).
SurfaceWaveOnset waveOnset(const std::vector<double>& gammas, int variant, double f, double width_d,
                           bool periodic, const std::vector<SurfaceWaveSummary>& points);

std::vector<SurfaceWaveOnset> waveOnsets(const SurfaceWavesConfig& c,
                                         const std::vector<SurfaceWaveSummary>& onset_points);

std::vector<VariantDissipation> variantDissipation(const SurfaceWavesConfig& c,
                                                   const std::vector<SurfaceWaveSummary>& points,
                                                   const std::vector<SurfaceWaveOnset>& onsets);

// Spearman's rho of gamma_c against e_eff over the entries with both (ties: mean ranks);
// `count` is how many there were (rho = NaN below 3).
void rankCorrelation(const std::vector<VariantDissipation>& d, double& rho, int& count);

}  // namespace granwave
