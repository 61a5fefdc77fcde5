#pragma once
// The on-disk contract of a fields file FIELDS.h5 (docs/fields.md), shared by its writer
// (FieldsFile.hpp) and its reader (FieldsReader.hpp) so the two cannot drift apart:
//
//   /grid/x [nx], /grid/z [nz]                 cell centres, m (lab frame)
//   /fields/<cell field> [phase][z][x]         count, area_fraction, velocity_x, velocity_z,
//                                              temperature, rotational_temperature
//   <root>/profiles/<profile> [phase][z]       temperature, velocity_z, rms_velocity_x,
//                                              area_fraction
//   <root>/blocks/profiles/<profile> [block][phase][z]    the same per block of cycles
//   <root>/phases/<series> [phase]             time, phase, plate_height, center_of_mass_height,
//                                              front_height, front_peak_temperature, and
//                                              (particle runs) kBudgetSeries below
//   <root>/fronts/<column> [episode]           kFrontColumns below
//   /states/period{1,2}                        <root> of the fields of each layer state
//                                              (attributes windows, pooled_cycles); /states has
//                                              windows_period1 and windows_period2
//   /patterns                                  attributes: the live classification
//   /period_doubling/{f2_strength, noise_strength, threshold} [window], episodes [episode][3]
//                                              (first cycle, cycles, period) and attributes
//   /xdmf/pNNNN/{area_fraction, temperature [nz][1][nx], velocity [nz][1][nx][3]}
//                                              (/fields and /xdmf only if the root attribute
//                                              cells is 1; both compressed)
//   /parameters                                attributes (kParameter*); scene (TOML text)
//
// <root> is "" for the whole run. Units as "unit" attributes. The hydro run file HYDRO.h5
// (studies/run_files/HydroRunFile.hpp) holds the continuum's lab-frame profiles under the same
// names (/grid/z, /profiles, /phases, /fronts), so one quantity has one name in both files.
#include <array>
#include <string>
#include <vector>

#include "coarse_grain/PhaseFields.hpp"
#include "coarse_grain/WaveFront.hpp"

namespace granwave {

inline constexpr const char* kFieldsFormat = "granwave-fields-1";

namespace fields_layout {

inline const std::string kGridX = "/grid/x";
inline const std::string kGridZ = "/grid/z";
inline const std::string kFields = "/fields";
inline const std::string kProfiles = "/profiles";
inline const std::string kBlockProfiles = "/blocks/profiles";
inline const std::string kPhases = "/phases";
inline const std::string kFronts = "/fronts";
inline const std::string kStates = "/states";
inline const std::string kPatterns = "/patterns";
inline const std::string kPeriodDoubling = "/period_doubling";
inline const std::string kXdmf = "/xdmf";
// Root attribute: 1 if the file holds the cells (/fields, /xdmf and the sidecar), 0 if they
// were left out (FieldsCells::left_out, the studies' cached runs).
inline const std::string kCellsAttribute = "cells";
inline const std::string kParameters = "/parameters";
inline const std::string kScene = "/parameters/scene";
inline std::string stateRoot(int period) { return kStates + "/period" + std::to_string(period); }

// Where hydro run files written before the names were shared kept the lab-frame rows and
// profiles (/lab_frame/z, /lab_frame/<profile>); read still, so earlier runs stay usable.
inline const std::string kEarlierLabFrame = "/lab_frame";

// A field of PhaseFields: its dataset name, unit and member.
struct FieldColumn {
  const char* name;
  const char* unit;
  std::vector<double> PhaseFields::*values;
};

inline const std::array<FieldColumn, 6> kCellFields{{
    {"count", "1", &PhaseFields::count},
    {"area_fraction", "1", &PhaseFields::area_fraction},
    {"velocity_x", "m s-1", &PhaseFields::velocity_x},
    {"velocity_z", "m s-1", &PhaseFields::velocity_z},
    {"temperature", "J", &PhaseFields::temperature},
    {"rotational_temperature", "J", &PhaseFields::rotational_temperature},
}};

inline const std::array<FieldColumn, 4> kProfileFields{{
    {"temperature", "J", &PhaseFields::profile_temperature},
    {"velocity_z", "m s-1", &PhaseFields::profile_velocity_z},
    {"rms_velocity_x", "m s-1", &PhaseFields::profile_rms_velocity_x},
    {"area_fraction", "1", &PhaseFields::profile_area_fraction},
}};

// The per-phase series (<root>/phases/<name>).
inline constexpr const char* kTime = "time";                 // s since the window's start
inline constexpr const char* kPhase = "phase";               // t/T, 0 .. cycles_per_window
inline constexpr const char* kPlateHeight = "plate_height";  // m
inline constexpr const char* kCenterOfMass = "center_of_mass_height";  // m
inline constexpr const char* kFrontHeight = "front_height";            // m
inline constexpr const char* kFrontPeak = "front_peak_temperature";    // T~_g / T0
// The layer's energy budget per phase interval (PhaseFields), J; particle runs only.
inline constexpr std::array<FieldColumn, 3> kBudgetSeries{{
    {"plate_work", "J", &PhaseFields::plate_work},
    {"pair_loss", "J", &PhaseFields::pair_loss},
    {"wall_loss", "J", &PhaseFields::wall_loss},
}};

// A column of the front table: one value per episode, stored as double.
struct FrontColumn {
  const char* name;
  const char* unit;
  double (*get)(const FrontEpisode&);
  void (*set)(FrontEpisode&, double);
  // The name the column had in hydro run files before the names were shared, or nullptr.
  const char* earlier_name;
};

// clang-format off
inline constexpr std::array<FrontColumn, 12> kFrontColumns{{
    {"first_phase", "1", [](const FrontEpisode& e) { return double(e.first_phase); },
     [](FrontEpisode& e, double v) { e.first_phase = static_cast<int>(v); }, nullptr},
    {"last_phase", "1", [](const FrontEpisode& e) { return double(e.last_phase); },
     [](FrontEpisode& e, double v) { e.last_phase = static_cast<int>(v); }, nullptr},
    {"speed", "m s-1", [](const FrontEpisode& e) { return e.speed; },
     [](FrontEpisode& e, double v) { e.speed = v; }, nullptr},
    // The speed's uncertainty. Hydro run files called it fit_error: without blocks of cycles
    // the fit's error is the whole error (WaveFront.hpp).
    {"speed_error", "m s-1", [](const FrontEpisode& e) { return e.speed_error; },
     [](FrontEpisode& e, double v) { e.speed_error = v; }, "fit_error"},
    {"fit_error", "m s-1", [](const FrontEpisode& e) { return e.fit_error; },
     [](FrontEpisode& e, double v) { e.fit_error = v; }, nullptr},
    {"block_spread", "m s-1", [](const FrontEpisode& e) { return e.block_spread; },
     [](FrontEpisode& e, double v) { e.block_spread = v; }, nullptr},
    {"blocks_used", "1", [](const FrontEpisode& e) { return double(e.blocks_used); },
     [](FrontEpisode& e, double v) { e.blocks_used = static_cast<int>(v); }, nullptr},
    {"gas_velocity_ahead", "m s-1", [](const FrontEpisode& e) { return e.gas_velocity_ahead; },
     [](FrontEpisode& e, double v) { e.gas_velocity_ahead = v; }, nullptr},
    {"speed_relative", "m s-1", [](const FrontEpisode& e) { return e.speed_relative; },
     [](FrontEpisode& e, double v) { e.speed_relative = v; }, nullptr},
    {"peak_temperature", "1", [](const FrontEpisode& e) { return e.peak_temperature; },
     [](FrontEpisode& e, double v) { e.peak_temperature = v; }, nullptr},
    {"start_above_plate", "m", [](const FrontEpisode& e) { return e.start_above_plate; },
     [](FrontEpisode& e, double v) { e.start_above_plate = v; }, nullptr},
    {"from_impact", "1", [](const FrontEpisode& e) { return e.from_impact ? 1.0 : 0.0; },
     [](FrontEpisode& e, double v) { e.from_impact = v > 0.5; }, nullptr},
}};
// clang-format on

// Attributes of /parameters.
inline constexpr const char* kFormat = "format";
inline constexpr const char* kSource = "source";
inline constexpr const char* kDiameter = "diameter";
inline constexpr const char* kMass = "mass";
inline constexpr const char* kFrequency = "frequency";
inline constexpr const char* kAmplitude = "amplitude";
inline constexpr const char* kT0 = "T0";
inline constexpr const char* kSamplesPerCycle = "samples_per_cycle";
inline constexpr const char* kCyclesPerWindow = "cycles_per_window";
inline constexpr const char* kBlocks = "blocks";
inline constexpr const char* kDiscardedCycles = "discarded_cycles";
inline constexpr const char* kPooledCycles = "pooled_cycles";  // also of each state's root
inline constexpr const char* kLayerPeriod = "layer_period";
inline constexpr const char* kMinCount = "min_count";
inline constexpr const char* kFrontThreshold = "front_threshold";
inline constexpr const char* kFrontLayerMinAreaFraction = "front_layer_min_area_fraction";

// Datasets of /period_doubling (its attributes, like those of /patterns, are named in
// FieldsFile.cpp and FieldsReader.cpp, as H5mdLayout.hpp leaves /parameters' to its two sides).
inline constexpr const char* kF2Strength = "f2_strength";
inline constexpr const char* kNoiseStrength = "noise_strength";
inline constexpr const char* kThreshold = "threshold";
inline constexpr const char* kEpisodes = "episodes";

// Attributes of /states and its roots.
inline constexpr const char* kWindows = "windows";
inline const std::string kStateWindows[2] = {"windows_period1", "windows_period2"};

}  // namespace fields_layout
}  // namespace granwave
