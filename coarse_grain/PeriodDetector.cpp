#include "coarse_grain/PeriodDetector.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numeric>
#include <stdexcept>
#include <string>

#include "coarse_grain/SteadyStateDetector.hpp"

namespace granwave {

namespace {

// Power spectrum |X_k|^2 of a real series (FFTW r2c; ESTIMATE planning is deterministic).
std::vector<double> powerSpectrum(std::vector<double> x) {
  const int n = static_cast<int>(x.size());
  std::vector<std::complex<double>> out(n / 2 + 1);
  fftw_plan plan =
      fftw_plan_dft_r2c_1d(n, x.data(), reinterpret_cast<fftw_complex*>(out.data()), FFTW_ESTIMATE);
  fftw_execute(plan);
  fftw_destroy_plan(plan);
  std::vector<double> power(out.size());
  for (std::size_t k = 0; k < out.size(); ++k) power[k] = std::norm(out[k]);
  return power;
}

}  // namespace

PeriodResult detectPeriod(const std::vector<double>& height, int discard_cycles,
                          const PeriodOptions& opt) {
  const int M = opt.samples_per_cycle;
  const int total = static_cast<int>(height.size()) / M;
  int K = total - discard_cycles;
  K -= K % 12;
  if (M < 4 || K < 12)
    throw std::invalid_argument("period detection needs at least 12 steady cycles, got " +
                                std::to_string(std::max(0, total - discard_cycles)));
  std::vector<double> x(height.begin() + static_cast<long>(total - K) * M,
                        height.begin() + static_cast<long>(total) * M);
  double mean = 0;
  for (double v : x) mean += v / x.size();
  for (double& v : x) v -= mean;
  const std::vector<double> P = powerSpectrum(std::move(x));
  const int nyquist = static_cast<int>(P.size()) - 1;

  PeriodResult r;
  r.cycles_used = K;
  r.strength.assign(opt.max_period + 1, 0.0);
  double harm = 0;
  for (int b = K; b <= nyquist; b += K) harm += P[b];
  r.harmonic_amplitude = 2.0 * std::sqrt(P[K]) / (static_cast<double>(K) * M);
  if (harm <= 0) return r;
  for (int p = 2; p <= opt.max_period; ++p) {
    double sub = 0;
    for (int j = 1; j * K / p <= nyquist; ++j) {
      if (j % p == 0) continue;
      // Leave out frequencies that belong to a smaller period (for p = 4: j = 2 is f/2).
      bool smaller = false;
      for (int q = 2; q < p; ++q) smaller = smaller || (j * q) % p == 0;
      if (!smaller) sub += P[j * K / p];
    }
    r.strength[p] = std::sqrt(sub / harm);
  }
  // A period-4 orbit also has power at f/2: the period is the least common multiple of
  // every subharmonic period present.
  for (int p = 2; p <= opt.max_period; ++p) {
    if (r.strength[p] > opt.threshold) r.period = std::lcm(r.period, p);
  }
  return r;
}

RunPeriod runPeriod(const std::vector<double>& com_height, int M) {
  if (M < 4)
    throw std::invalid_argument("period detection needs at least 4 samples per cycle, got " +
                                std::to_string(M));
  const int cycles = static_cast<int>(com_height.size()) / M;
  RunPeriod r;
  r.discarded = std::max({3, cycles / 5, steadyCycles(com_height, M)});
  r.result = detectPeriod(com_height, r.discarded, {M});
  return r;
}

}  // namespace granwave
