#pragma once
// The scene: every user-facing parameter of a granwave run, in SI units, with the paper's
// values as defaults (K. Huang, "Internal and surface waves in vibrofluidized granular
// materials: role of cohesion", Methods and Table I). Parsing and validation live in SceneParser;
// the derived quantities (A, v0, T0, t_c, q, v_c) in SceneDerived. No physics beyond those formulas
// here.
#include <cstdint>
#include <optional>
#include <string>

namespace granwave {

enum class RestitutionKind { Constant, Dry, Wet };
enum class InitialPlacement { Random, Lattice };
enum class HydroRestitutionModel { Constant, Velocity };
enum class HydroTransport { JenkinsRichman, GarzoDufty };
enum class HydroPairCorrelation { Luding, Henderson };
enum class HydroParticles { Smooth, Rough };
// How the continuum's plate and lid meet the layer: a stiff spring with a dashpot, or a hard
// wall whose contact and lift-off are events (docs/hydro.md, "Walls").
enum class HydroWalls { Spring, Hard };
// The readings of the paper's "tangential COR set to 1" (walls) and "e_n = e_t = 1" (TC
// collisions): smooth (tangential contact velocity kept), rough-elastic (reversed: Luding's
// e_t = +1), or the particles' Coulomb friction law. docs/scenes.md, "Readings".
enum class ContactTangential { Smooth, RoughElastic, Coulomb };
// "Only the first collision of each particle within this time scale is inelastic": the TC
// window restarts at every collision (rolling) or at the first collision after it closed
// (anchored).
enum class TcWindow { Rolling, Anchored };
// Putting particles at rest on the plate to sleep (docs/physics.md, "Resting contacts",
// item 7): "auto" = only where the drive cannot lift the layer (no drive, or Gamma <= 1).
enum class SleepRule { Auto, On, Off };
// The velocity unit u of the dry law e = 1 - kappa (v_n / u)^(1/5): 1 m/s, sqrt(g d), 1 cm/s.
enum class KappaUnits { Si, GravityDiameter, Cgs };

struct ParticlesSpec {
  int count = 300;
  double diameter = 0.002;       // m
  double density = 2580.0;       // kg/m^3
  double youngs_modulus = 63e9;  // Pa
  double poisson_ratio = 0.22;
};

struct ContainerSpec {
  double width = 0.06;   // m (30 d)
  double height = 0.06;  // m (30 d)
  bool periodic_x = false;
  bool periodic_z = false;  // only without drive
};

struct DriveSpec {
  double frequency = 10.0;  // Hz; 0 = no drive
  // Exactly one of gamma / amplitude is given; the other is derived.
  std::optional<double> gamma = 4.0;
  std::optional<double> amplitude;  // m
};

struct ContactSpec {
  RestitutionKind restitution = RestitutionKind::Dry;
  double e = 0.9;      // constant law
  double kappa = 0.1;  // dry law, in the unit kappa_units names
  KappaUnits kappa_units = KappaUnits::Si;
  double e_inf = 0.91;             // wet law
  double stokes_critical = 40.0;   // wet law, St_c
  double viscosity = 1.0e-3;       // wet law, Pa s
  double friction = 0.5;           // mu; 0 switches rotation off
  double tangential_limit = 0.35;  // e_t0
  // "Set to 1" in the paper (walls, TC collisions) read by default as e_t = -1 (tangential
  // relative velocity unchanged) in Luding's convention: see docs/physics.md.
  ContactTangential wall_tangential = ContactTangential::Smooth;
  ContactTangential tc_tangential = ContactTangential::Smooth;
  TcWindow tc_window = TcWindow::Rolling;
  SleepRule sleep = SleepRule::Auto;
  bool tc_enabled = true;
  std::optional<double> tc_time;  // s; empty = paper's formula ("auto")
  // Below this separation speed after a wall collision, a particle pressed on by the wall
  // rests on (rides) it until the wall's acceleration falls below -g. See docs/physics.md.
  double rest_velocity = 1e-6;  // m/s
};

struct InitialSpec {
  std::optional<double> temperature;  // J per particle (Maxwellian); empty = paper's start
  InitialPlacement placement = InitialPlacement::Random;
};

struct RunSpec {
  double duration = 15.0;        // s
  int phases_per_cycle = 100;    // M, driven scenes
  double record_interval = 0.0;  // s, undriven scenes (0 = duration / 100)
  int trajectory_stride = 1;     // write positions every k-th record
  std::uint64_t seed = 1;
  double gravity = 9.81;  // m/s^2, magnitude (points along -z)
};

enum class HydroStart { Settled, Spread };

struct HydroSpec {
  // 1: the horizontally averaged layer; 2: the x-z plane in columns (docs/hydro.md, "The 2D
  // model"), periodic or between side walls as container.periodic_x says.
  int dimensions = 1;
  int cells = 100;  // Lagrangian cells of equal mass (per column in 2D)
  int columns = 0;  // 2D: columns across the width; 0 = one per 4 d
  // 2D: the RMS of the seeded relative perturbation of the columns' masses (run.seed).
  double perturbation = 0.01;
  // 2D: the vertical remap (hydro/Layer2DRemap.hpp) when a cell's mass falls to this share of
  // its column's and layer's; 0 = never.
  double remap_share = 0.25;
  double rtol = 1e-4;  // CVODE relative tolerance
  double atol = 1e-8;  // absolute tolerance, relative to close packing (docs/hydro.md)
  HydroRestitutionModel restitution_model = HydroRestitutionModel::Velocity;
  HydroTransport transport = HydroTransport::JenkinsRichman;
  bool side_walls = false;  // side-wall dissipation as a volumetric sink (x not periodic)
  // Integrate the layer's energy budget with it (docs/hydro.md, "Energy budget").
  bool energy_budget = false;
  HydroPairCorrelation pair_correlation = HydroPairCorrelation::Luding;
  double contact_pressure =
      0.0;  // scale of an elastic contact pressure in rho_cp g sigma (0 = none)
  HydroParticles particles = HydroParticles::Smooth;  // rough: rotation as a field
  // Where the run starts: the layer settled on the plate, or spread evenly over the container
  // as the particle engine places its grains; at this granular temperature, in T0 = m v0^2 / 2.
  HydroStart start = HydroStart::Spread;
  double initial_temperature = 1e-4;
  // The numerical parameters of the discrete operator (hydro/GranularHydro1D.hpp,
  // HydroRegularisation); docs/hydro.md shows the answers do not depend on them.
  double artificial_viscosity = 0.25;     // c2 of q = rho c2 du^2
  HydroWalls walls = HydroWalls::Spring;  // hard: the two wall_contact keys are not used (1D)
  double wall_contact_range = 0.05;       // sigma
  double wall_contact_stiffness = 0.01;   // sigma
  double packing_width = 1e-4;            // of the close-packed density
  double temperature_floor = 1e-30;       // g sigma
};

struct Scene {
  ParticlesSpec particles;
  ContainerSpec container;
  DriveSpec drive;
  ContactSpec contact;
  InitialSpec initial;
  RunSpec run;
  HydroSpec hydro;
};

}  // namespace granwave
