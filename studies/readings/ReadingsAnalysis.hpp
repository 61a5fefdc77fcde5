#pragma once
// The numbers of the readings study: per reading, the paper's statements measured over the
// seeds (fractions with their 68 % Wilson interval, means with standard errors), a verdict
// per statement, and what the reading costs physically; written under /results/readings
// (docs/studies.md).
#include <string>
#include <vector>

#include "h5/File.hpp"
#include "studies/contract/Study.hpp"
#include "studies/readings/ReadingsStudy.hpp"
#include "studies/statistics/Measurement.hpp"

namespace granwave {

// k of n seeds, with the 68 % Wilson score interval of the fraction.
struct SeedFraction {
  int count = 0, of = 0;
  double low = 0, high = 1;
  double fraction() const { return of > 0 ? static_cast<double>(count) / of : kNoFraction; }
  static constexpr double kNoFraction = -1;
};
SeedFraction seedFraction(int count, int of);

enum class Verdict { Holds, Fails, Undecided, NoData };
const char* verdictName(Verdict v);
// A majority statement: holds if the interval lies above 1/2, fails if below.
Verdict majority(const SeedFraction& f);
// A number against the paper's: holds within 2 sigma (sigma^2 = error^2 + tolerance^2), fails
// beyond; a number whose own error exceeds the tolerance cannot hold (it would agree with
// almost anything): it is undecided unless it fails even so.
Verdict agrees(const Measurement& m, double paper, double tolerance);

// The paper's statements, the rows of the report's table.
enum Statement {
  kDryPeriod2,
  kWetPeriod2,
  kDryMinimumPhase,
  kWetMinimumPhase,
  kDryWaves,
  kNoWetWaves,
  kCrystalAtHighF,
  kWeakFront,
  kStrongFront,
  kMomentumRatio,
  kStatements
};
struct StatementText {
  const char* paper;  // what the paper says, with its number
};
extern const StatementText kStatementTexts[kStatements];

struct ReadingOutcome {
  SeedFraction period2[kLaws];                    // at (f, wave_gamma)
  Measurement minimum_phase[kLaws];               // t/T of the lowest CM point, mean over seeds
  double phase_resolution = 0;                    // 1 / phases per cycle
  std::vector<SeedFraction> waves[kLaws];         // per Gamma of [checks] gammas
  std::vector<SeedFraction> crystal_high[kLaws];  // per high frequency, at high_gamma
  Measurement weak_front, strong_front;           // wet, m/s
  Measurement momentum_ratio;                     // r~_x over the wave, mean over seeds
  double tc_elastic_share[kLaws] = {0, 0};        // of all collisions at the wave point
  double e_dry_1ms = 0, e_dry_v0 = 0;             // dry law at 1 m/s and at the plate's v0
  double cpu_seconds = 0;
  int failed_runs = 0;
  std::string first_failure;
  Verdict verdict[kStatements] = {};
  std::string measured[kStatements];  // the number behind each verdict
  int holds() const;
};

struct ReadingsResults {
  std::vector<ReadingOutcome> readings;
};

ReadingsResults analyseReadings(const ReadingsConfig& config, const RunSet& runs);
void writeReadingsResults(h5::File& file, const ReadingsConfig& config,
                          const ReadingsResults& results);

}  // namespace granwave
