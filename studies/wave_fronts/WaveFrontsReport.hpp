#pragma once
// The wave-fronts study's report, section by section (docs/studies.md): the paper's scene,
// temperature profiles and space-time plots, the N and wet-law sweeps (this file's .cpp), cost
// against accuracy, where each method fails, the model hierarchy and LAMMPS
// (WaveFrontsMethodsReport.cpp). Figures, tables and prose only.
#include "studies/report/Report.hpp"
#include "studies/wave_fronts/WaveFrontsAnalysis.hpp"

namespace granwave {

void reportWaveFronts(const WaveFrontsConfig& config, const WaveFrontsResults& results,
                      Report& report);

void costSection(const WaveFrontsConfig& config, const CostAccuracy& cost, Report& report);
void failureSection(const WaveFrontsConfig& config, const FailureMap& failures, Report& report);
// Also the report's summary, which ends with the models' verdict.
void modelSection(const WaveFrontsConfig& config, const WaveFrontsResults& results, Report& report);
// The layer's state: shares of seeds and time in the period-2 state, state-conditioned fronts.
void stateSection(const WaveFrontsResults& results, Report& report);
void lammpsSection(const WaveFrontsConfig& config, const LammpsComparison& lammps,
                   const PaperLaw& dry, Report& report);

}  // namespace granwave
