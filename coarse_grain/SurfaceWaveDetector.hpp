#pragma once
// Standing subharmonic surface waves (paper Sec. III, Fig. 2: the dry layer at f = 10 Hz,
// Gamma = 4 forms them, the wet one does not; stability diagram Fig. 3, filled squares).
//
// Spectrum of one profile. The mean-removed surface h_i - <h> (SurfaceProfile, N columns of
// width w, L = N w) is expanded in the modes the boundary allows:
//
//   side walls:  h_i - <h> = sum_{m>=1} a_m cos(pi m x_i / L),   x_i = (i + 1/2) w,
//                a DCT-II (FFTW REDFT10). No flux through a vertical wall means a zero surface
//                slope there (Neumann), so these cosines are the sloshing eigenmodes of the
//                box and a wave with a non-integer number of wavelengths in L_x is still one
//                mode. A plain DFT would treat the profile as periodic, see a jump between
//                x = L and x = 0 and spread it over every mode. Mode m holds m half
//                wavelengths: lambda = 2 L / m.
//   periodic x:  h_i - <h> = sum_{m>=1} Re(a_m exp(2 pi i m x_i / L)), a real-to-complex DFT;
//                a_m is complex (the wave's position is free). lambda = L / m.
//
// Both are normalised so that |a_m| is the amplitude (half the crest-to-trough height) of a
// pure mode m. Modes with lambda < min_wavelength are left out: the columns are one d wide,
// so lambda = 2 d is the sampling limit, and alternating columns are the grain-scale
// roughness of the surface, not a collective wave.
//
// Series of profiles at one drive phase in consecutive cycles c = 0 .. K-1. The dominant
// mode m* maximises the pooled power sum_c |a_m(c)|^2; its amplitude is the rms over cycles,
// sqrt(<|a_m*(c)|^2>_c). A standing wave at f/2 locked to the drive (period-doubled layer,
// Melo et al. PRL 72, 172 (1994); Clement et al. PRL 77, 4986 (1996)) is, at a fixed phase,
// the same spatial mode with the opposite sign in the next cycle: Re(a(c+1) conj a(c)) < 0.
// The alternation fraction is the share of consecutive pairs where that holds: 1 for a
// subharmonic standing wave, 0 for a pattern repeating every cycle (harmonic response),
// about 1/2 for a mode that only holds noise. Detection needs both
//
//   amplitude >= amplitude_threshold  and  alternation fraction >= min_alternation.
//
// The subharmonic amplitude |<(-1)^c a_m*(c)>_c| (the f/2 part that survives averaging over
// cycles, noise falling as 1/sqrt(K)) is reported too.
//
// A kink (two flat domains in antiphase, KinkDetector.hpp) is a step in h that also flips
// sign each cycle; its spectrum is dominated by the lowest mode, so this detector fires on it
// as well. Decide kinks first, see docs/classification.md.
#include <complex>
#include <vector>

#include "coarse_grain/SurfaceProfile.hpp"

namespace granwave {

struct SurfaceWaveOptions {
  // Wave amplitude (half crest-to-trough) in d. 0.5 d means a crest-to-trough height of one
  // diameter, the smallest deformation that cannot be the discreteness of the surface; it is
  // also well above the noise floor: columns with independent roughness sigma_h give
  // |a_m| ~ 2 sigma_h / sqrt(N) per mode, 0.1 d for sigma_h = 0.3 d and N = 30 (paper).
  double amplitude_threshold = 0.5;
  // Share of consecutive cycle pairs with a sign flip of the dominant mode. Noise flips at
  // random (1/2 on average); 0.75 asks for a clear majority without demanding that every
  // cycle be clean.
  double min_alternation = 0.75;
  // Shortest wavelength counted as a surface wave, in d (see above).
  double min_wavelength = 4.0;
};

struct SurfaceSpectrum {
  // a_m in m for m = 0 .. M (M = N - 1 with walls, N / 2 periodic); a_0 = 0 (mean removed).
  // Real (imaginary part 0) with walls.
  std::vector<std::complex<double>> mode;
  double mean_height = 0;   // m, <h>
  int dominant_mode = 0;    // m* among the admitted modes (0 if the profile is flat)
  double amplitude_d = 0;   // |a_m*| / d
  double wavelength_d = 0;  // lambda(m*) / d (0 if m* = 0)
};

struct SurfaceWaveResult {
  bool detected = false;
  int mode = 0;                        // m*
  double wavelength_d = 0;             // lambda(m*) / d
  double amplitude_d = 0;              // rms over cycles of |a_m*| / d
  double subharmonic_amplitude_d = 0;  // |<(-1)^c a_m*(c)>_c| / d
  double alternation_fraction = 0;     // share of pairs with Re(a(c+1) conj a(c)) < 0
  int cycles = 0;                      // K
};

// Wavelength of mode m (m >= 1) in d for a profile's boundary type and width.
double modeWavelength(const SurfaceProfile& profile, int m);

// Spectrum of one profile (no temporal information). Throws std::invalid_argument for fewer
// than 2 columns or a non-positive diameter.
SurfaceSpectrum surfaceSpectrum(const SurfaceProfile& profile,
                                const SurfaceWaveOptions& options = {});

// `same_phase_cycles[c]` is the surface at one drive phase in cycle c (consecutive cycles).
// Throws std::invalid_argument for fewer than 2 profiles or profiles of different geometry.
SurfaceWaveResult detectStandingWave(const std::vector<SurfaceProfile>& same_phase_cycles,
                                     const SurfaceWaveOptions& options = {});

}  // namespace granwave
