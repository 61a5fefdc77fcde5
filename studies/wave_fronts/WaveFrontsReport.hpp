#pragma once
// The wave-fronts study's report, section by section (docs/studies.md): the paper's scene,
// temperature profiles and space-time plots (this file's .cpp), the N and wet-law sweeps
// (WaveFrontsSweepsReport.cpp; the fronts' transits, WaveFrontsTransitsReport.cpp), the layer's
// states (WaveFrontsStatesReport.cpp), the cheapest model per scene (CheapestModelReport.cpp), and
// the methods comparison's sections (studies/method_comparison/MethodComparisonReport.hpp).
// Figures, tables and prose only.
#include <string>

#include "studies/method_comparison/MethodComparisonReport.hpp"
#include "studies/report/Report.hpp"
#include "studies/wave_fronts/WaveFrontsAnalysis.hpp"

namespace granwave {

void reportWaveFronts(const WaveFrontsConfig& config, const WaveFrontsResults& results,
                      Report& report);

// The layer's depth N (Fig. 6a) and the wet law's parameters (Fig. 6b).
void depthSection(const WaveFrontsConfig& config, const WaveFrontsResults& results, Report& report);
void wetLawSection(const WaveFrontsResults& results, Report& report);
// The N sweep's fronts by their transits through the layer's mass, particles beside the
// continuum with both periods (WaveFrontsTransitsReport.cpp).
void transitDepthTable(const WaveFrontsConfig& config, const WaveFrontsResults& results,
                       ReportSection& section);
// The layer's state: shares of seeds and time in the period-2 state, state-conditioned fronts.
void stateSection(const WaveFrontsResults& results, Report& report);
// The energy budget phase by phase on the paper's scene, particles and continuum.
void energyBudgetSection(const WaveFrontsResults& results, Report& report);
// Cost per answer at equal accuracy and the cheapest model per scene; returns its headline line.
std::string cheapestModelSection(const WaveFrontsConfig& config, const WaveFrontsResults& results,
                                 Report& report);

}  // namespace granwave
