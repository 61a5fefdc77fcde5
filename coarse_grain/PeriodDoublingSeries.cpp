#include "coarse_grain/PeriodDoublingSeries.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace granwave {

namespace {

// tau = 1 + 2 sum_k rho_k over the initial positive autocorrelations; 0 if the series is
// constant (no estimate).
double integratedAutocorrelation(const std::vector<int>& s) {
  const std::size_t n = s.size();
  double mean = 0;
  for (int v : s) mean += static_cast<double>(v) / static_cast<double>(n);
  double c0 = 0;
  for (int v : s) c0 += (v - mean) * (v - mean);
  if (c0 <= 0) return 0;
  double tau = 1;
  for (std::size_t k = 1; k < n; ++k) {
    double ck = 0;
    for (std::size_t i = 0; i + k < n; ++i) ck += (s[i] - mean) * (s[i + k] - mean);
    const double rho = ck / c0;
    if (rho <= 0) break;
    tau += 2 * rho;
  }
  return tau;
}

// The six smallest shifts (in bins) of the f/2 comb that land on no harmonic and no
// subharmonic of periods 2-4 for a window of K = 12 m cycles: f/2 lines sit at 6m j (j odd),
// period 3 at multiples of 4m, period 4 at multiples of 3m.
std::vector<int> noiseShifts(int K) {
  const int m = K / 12;
  std::vector<int> shifts;
  for (int d = 1; shifts.size() < 6; ++d)
    for (int s : {d, -d}) {
      const int at = 6 * m + s;  // every odd j gives the same residues
      if (((at % (3 * m)) != 0) && ((at % (4 * m)) != 0)) shifts.push_back(s);
    }
  shifts.resize(6);
  return shifts;
}

double combPower(const std::vector<double>& P, int K, int shift) {
  double sum = 0;
  const int nyquist = static_cast<int>(P.size()) - 1;
  for (int j = 1; j * K / 2 + shift <= nyquist; j += 2)
    if (j * K / 2 + shift >= 1) sum += P[j * K / 2 + shift];
  return sum;
}

}  // namespace

F2Window f2Window(const double* window, int K, int M, double floor) {
  if (K <= 0 || K % 12 != 0 || M < 4)
    throw std::invalid_argument("f/2 window of " + std::to_string(K) + " cycles and " +
                                std::to_string(M) +
                                " samples per cycle; a positive multiple of 12 cycles and at "
                                "least 4 samples are needed");
  const int n = K * M;
  std::vector<double> x(window, window + n);
  double mean = 0;
  for (double v : x) mean += v / n;
  for (double& v : x) v -= mean;
  std::vector<std::complex<double>> out(n / 2 + 1);
  // FFTW r2c with ESTIMATE planning: deterministic.
  fftw_plan plan =
      fftw_plan_dft_r2c_1d(n, x.data(), reinterpret_cast<fftw_complex*>(out.data()), FFTW_ESTIMATE);
  fftw_execute(plan);
  fftw_destroy_plan(plan);
  std::vector<double> P(out.size());
  for (std::size_t k = 0; k < out.size(); ++k) P[k] = std::norm(out[k]);
  double harm = 0;
  for (std::size_t b = K; b < P.size(); b += K) harm += P[b];
  F2Window w;
  w.f2 = out[K / 2];
  w.threshold = floor;
  if (harm <= 0) return w;
  double noise = 0;
  const std::vector<int> shifts = noiseShifts(K);
  for (int s : shifts) noise += combPower(P, K, s) / static_cast<double>(shifts.size());
  w.strength = std::sqrt(combPower(P, K, 0) / harm);
  w.noise_strength = std::sqrt(noise / harm);
  w.threshold = std::max(floor, 3 * w.noise_strength);
  w.period2 = w.strength > w.threshold;
  return w;
}

void wilsonInterval(double p, double n, double& low, double& high) {
  constexpr double z = kZ95;
  const double z2n = z * z / n;
  const double centre = (p + 0.5 * z2n) / (1 + z2n);
  const double half = z * std::sqrt(p * (1 - p) / n + 0.25 * z2n / n) / (1 + z2n);
  low = std::max(0.0, centre - half);
  high = std::min(1.0, centre + half);
}

PeriodDoublingSeries periodDoublingSeries(const std::vector<double>& com, int M, int discard,
                                          int window, double floor) {
  if (window <= 0 || window % 12 != 0)
    throw std::invalid_argument("period-doubling series: window of " + std::to_string(window) +
                                " cycles; a positive multiple of 12 is needed");
  const int total = M > 0 ? static_cast<int>(com.size()) / M : 0;
  const int first = std::max(0, discard + (discard % 2));
  const int windows = (total - first) / window;
  if (M < 4 || windows < 1)
    throw std::invalid_argument("period-doubling series needs at least one window of " +
                                std::to_string(window) + " steady cycles, got " +
                                std::to_string(std::max(0, total - first)));
  PeriodDoublingSeries r;
  r.window_cycles = window;
  r.first_cycle = first;
  for (int w = 0; w < windows; ++w) {
    const int start = first + w * window;
    const F2Window fw = f2Window(com.data() + static_cast<long>(start) * M, window, M, floor);
    r.f2_strength.push_back(fw.strength);
    r.noise_strength.push_back(fw.noise_strength);
    r.threshold.push_back(fw.threshold);
    r.period2.push_back(fw.period2 ? 1 : 0);
    r.period2_share += static_cast<double>(r.period2.back()) / windows;
    if (w > 0 && r.period2[w] == r.period2[w - 1]) {
      r.episodes.back().cycles += window;
    } else {
      r.episodes.push_back({start, window, fw.period2 ? 2 : 1});
    }
  }
  r.switches = static_cast<int>(r.episodes.size()) - 1;
  const double tau = integratedAutocorrelation(r.period2);
  r.effective_windows = tau > 0 ? std::min<double>(windows, windows / tau) : 1.0;
  wilsonInterval(r.period2_share, r.effective_windows, r.share_low, r.share_high);
  return r;
}

}  // namespace granwave
