#include "hydro/GranularHydro1D.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "hydro/LayerCell.hpp"

namespace granwave::hydro {

namespace {

// Blocks of the stencil that reach one unknown: its own and two on each side. Columns of
// blocks five apart never meet in a row, so 5 K colours give the whole band in one pass.
constexpr int kBlockColours = 5;

double closePackedDensity(const ConstitutiveModel& m) {
  return kHexagonalClosePacking * m.mass / m.diskArea();
}

}  // namespace

template <class S>
struct GranularHydro1D::Workspace {
  explicit Workspace(int cells)
      : rho(cells),
        length(cells),
        theta(cells),
        du(cells),
        stress(cells),
        exchange(cells),
        spin(cells),
        local(cells),
        heat(cells + 1) {}
  // Per cell: density, length, temperature, velocity jump, normal stress Pi, and for rough
  // particles the collisional rates of theta (tangential part) and theta_r; closures.
  std::vector<S> rho, length, theta, du, stress, exchange, spin;
  std::vector<LocalState<S>> local;
  // Heat flux through each node, upward (W/m).
  std::vector<S> heat;
};

template <int Colours>
struct GranularHydro1D::JetWorkspace {
  explicit JetWorkspace(int cells, int n) : w(cells), U(n), dU(n) {}
  Workspace<Jet<Colours>> w;
  std::vector<Jet<Colours>> U, dU;
};

GranularHydro1D::GranularHydro1D(const HydroGeometry& g, const ConstitutiveModel& model,
                                 double column_mass, const HydroRegularisation& numerics,
                                 bool energy_budget)
    : g_(g),
      model_(model),
      numerics_(numerics),
      m_c_(column_mass / g.cells),
      vars_(model.rough.enabled ? 4 : 3),
      theta_unit_(std::max(g.gravity, 1.0) * model.sigma),
      energy_budget_(energy_budget),
      reg_{model.packingLimit() * model.mass / model.diskArea(),
           numerics.packing_width * model.mass / model.diskArea(),
           1e-6 * model.sigma,
           numerics.temperature_floor * std::max(g.gravity, 1.0) * model.sigma,
           1e-4 * std::sqrt(std::max(g.gravity, 1.0) * model.sigma),
           closePackedDensity(model) * std::max(g.gravity, 1.0) * model.sigma},
      values_(std::make_unique<Workspace<double>>(g.cells)) {
  if (rough())
    rough_jets_ = std::make_unique<JetWorkspace<20>>(g.cells, size());
  else
    smooth_jets_ = std::make_unique<JetWorkspace<15>>(g.cells, size());
}

GranularHydro1D::~GranularHydro1D() = default;

std::string GranularHydro1D::componentName(int k) const {
  const int j = k / vars_;
  switch (k % vars_) {
    case 0:
      return "node " + std::to_string(j) + ", height";
    case 1:
      return "node " + std::to_string(j) + ", velocity";
    case 2:
      return "cell " + std::to_string(j) + ", temperature";
    default:
      return "cell " + std::to_string(j) + ", rotational temperature";
  }
}

double GranularHydro1D::contactStress(double gap, double speed, double rho, double c) const {
  const WallContact<double> w = wallContact(gap, model_.sigma, reg_.contact_scale, numerics_);
  const double damping = rho * c + 2 * std::sqrt(w.stiffness * 0.5 * m_c_);
  return w.elastic + damping * std::max(speed, 0.0) * w.indicator;
}

namespace {

// Heat fluxes through interior nodes, central in the temperature.
template <class S, class W>
void heatFluxes(int N, W& w) {
  for (int j = 1; j < N; ++j) {
    const S kappa = 0.5 * (w.local[j - 1].kappa_theta + w.local[j].kappa_theta);
    w.heat[j] = -kappa * (w.theta[j] - w.theta[j - 1]) / (0.5 * (w.length[j - 1] + w.length[j]));
  }
}

}  // namespace

// Cells: density, temperature, closures, stress, and the rough particles' exchange.
template <class S>
void GranularHydro1D::cellStates(const S* U, Workspace<S>& w) const {
  for (int i = 0; i < g_.cells; ++i) cellState(U, i, w);
}

template <class S>
void GranularHydro1D::cellState(const S* U, int i, Workspace<S>& w) const {
  using std::exp;
  const double c2 = numerics_.quadratic_viscosity;
  const EffectiveCell<S> c = effectiveCell(reg_, m_c_, theta_unit_, U[heightIndex(i)],
                                           U[heightIndex(i + 1)], U[temperatureIndex(i)]);
  w.rho[i] = c.rho;
  w.length[i] = c.length;
  w.theta[i] = c.theta;
  w.local[i] = model_.evaluate(c.rho, c.theta);
  const S du = U[velocityIndex(i + 1)] - U[velocityIndex(i)];
  // compression -> 1 for du < 0, -> 0 for du > 0; q = rho c2 du^2 there and exactly 0 at
  // du = 0, so a resting layer feels none.
  const S compression = 0.5 * (1.0 - du / smoothAbs(du, reg_.u_width));
  const S q = c.rho * compression * c2 * du * du;
  w.du[i] = du;
  w.stress[i] = w.local[i].p + q - w.local[i].viscosity * du / c.length;
  if (!rough()) return;
  const S spin = theta_unit_ * exp(U[rotationIndex(i)]) + reg_.theta_min;
  const S nu = c.rho * (model_.diskArea() / model_.mass);
  model_.rough.rates(nu, w.local[i].g2, w.local[i].phi_p, c.theta, spin, model_.sigma,
                     w.exchange[i], w.spin[i]);
}

template <class S>
std::pair<S, S> GranularHydro1D::wallReactions(double t, const Workspace<S>& w) const {
  // A held boundary node (half a cell) at rest: the wall balances its weight and the stress
  // of its cell, plate below node 0 and lid above node N.
  const double weight = 0.5 * m_c_ * effectiveGravity(t);
  return {w.stress[0] + weight, w.stress[g_.cells - 1] - weight};
}

template <class S>
std::pair<WallExchange<S>, WallExchange<S>> GranularHydro1D::wallExchanges(double t, const S* U,
                                                                           const Workspace<S>& w,
                                                                           WallHold hold) const {
  const int N = g_.cells;
  if (hardWalls()) {
    const S zero = constantLike(U[0], 0.0);
    const auto [plate, lid] = wallReactions(t, w);
    // A held node's cell loses the particles' wall collisions' energy, as in the spring's
    // contact; the landing's loss of the node's motion is an event (wallEvent).
    const auto held = [&](bool on, const S& reaction, const LocalState<S>& l) {
      return on ? WallExchange<S>{reaction, zero, l.wall_loss * l.p_kinetic, zero}
                : WallExchange<S>{zero, zero, zero, zero};
    };
    return {held(hold.plate, plate, w.local[0]), held(hold.lid, lid, w.local[N - 1])};
  }
  const double sigma = model_.sigma, scale = reg_.contact_scale, u_width = reg_.u_width;
  return {wallExchange(U[heightIndex(0)], S(-U[velocityIndex(0)]), w.local[0], w.rho[0], sigma,
                       scale, u_width, 0.5 * m_c_, numerics_),
          wallExchange(S(g_.height - U[heightIndex(N)]), U[velocityIndex(N)], w.local[N - 1],
                       w.rho[N - 1], sigma, scale, u_width, 0.5 * m_c_, numerics_)};
}

template <class S>
int GranularHydro1D::residual(double t, const S* U, S* dU, Workspace<S>& w, WallHold hold) const {
  for (int k = 0; k < layerSize(); ++k)
    if (!std::isfinite(value(U[k]))) return 1;
  for (int k = layerSize(); k < size(); ++k) dU[k] = constantLike(U[0], 0.0);  // quadratures
  const int N = g_.cells;
  cellStates(U, w);
  heatFluxes<S>(N, w);
  const auto [plate, lid] = wallExchanges(t, U, w, hold);
  w.heat[0] = -plate.loss;  // the energy the collisions take leaves through the walls
  w.heat[N] = lid.loss;
  const double geff = effectiveGravity(t);
  // Nodes: the stress below pushes up, the stress above pushes down; a held node rests.
  for (int j = 0; j <= N; ++j) {
    const S below = j == 0 ? plate.stress : w.stress[j - 1];
    const S above = j == N ? lid.stress : w.stress[j];
    const double mass = j == 0 || j == N ? 0.5 * m_c_ : m_c_;
    dU[heightIndex(j)] = U[velocityIndex(j)];
    dU[velocityIndex(j)] = (below - above) / mass - geff;
    if ((j == 0 && hold.plate) || (j == N && hold.lid))
      dU[heightIndex(j)] = dU[velocityIndex(j)] = constantLike(U[0], 0.0);
  }
  // Cells: work of the kinetic pressure and the viscosities, heat conduction, cooling.
  for (int i = 0; i < N; ++i) {
    const LocalState<S>& l = w.local[i];
    const S q = w.stress[i] - l.p + l.viscosity * w.du[i] / w.length[i];
    S power = -(l.p_kinetic + q) * w.du[i] + l.viscosity * w.du[i] * w.du[i] / w.length[i] -
              (w.heat[i + 1] - w.heat[i]) - l.cooling * w.length[i];
    if (model_.side_wall_width > 0)
      power -= 2.0 / model_.side_wall_width * l.wall_loss * l.p_kinetic * w.length[i];
    if (i == 0) power += plate.heating;
    if (i == N - 1) power += lid.heating;
    // d(ln theta)/dt = (d theta/dt) / theta, with the theta the unknown holds (without the
    // closures' floor), so that m_c theta ds/dt is exactly the cell's power.
    const S theta = theta_unit_ * exp(U[temperatureIndex(i)]);
    dU[temperatureIndex(i)] = power / (m_c_ * theta);
    if (!rough()) continue;
    dU[temperatureIndex(i)] += w.exchange[i] / theta;
    dU[rotationIndex(i)] = w.spin[i] / (theta_unit_ * exp(U[rotationIndex(i)]));
  }
  for (int k = 0; k < layerSize(); ++k)
    if (!std::isfinite(value(dU[k]))) return 1;
  return 0;
}

GranularHydro1D::EnergyRates GranularHydro1D::energyRates(double t, const double* U,
                                                          WallHold hold) const {
  Workspace<double>& w = *values_;
  const int N = g_.cells;
  cellStates(U, w);
  const auto [plate, lid] = wallExchanges(t, U, w, hold);
  EnergyRates r;
  // The plate pushes node 0 up and the lid pushes node N down; both move with the plate.
  r.plate_work = (plate.stress - lid.stress) * g_.plateVelocity(t);
  r.wall_loss = plate.loss + lid.loss;
  for (int i = 0; i < N; ++i) {
    const LocalState<double>& l = w.local[i];
    r.collisional_loss += l.cooling * w.length[i];
    if (model_.side_wall_width > 0)
      r.side_wall_loss += 2.0 / model_.side_wall_width * l.wall_loss * l.p_kinetic * w.length[i];
    // Per unit mass: translation theta, rotation theta_r / 2 (one rotational degree of freedom).
    if (rough()) r.friction_loss -= m_c_ * (w.exchange[i] + 0.5 * w.spin[i]);
  }
  return r;
}

double GranularHydro1D::labEnergy(double t, const double* U) const {
  const int N = g_.cells;
  const double zb = g_.plateHeight(t), vb = g_.plateVelocity(t), g = g_.gravity;
  double E = 0;
  for (int j = 0; j <= N; ++j) {
    const double m = j == 0 || j == N ? 0.5 * m_c_ : m_c_, u = U[velocityIndex(j)] + vb;
    E += 0.5 * m * u * u + m * g * (U[heightIndex(j)] + zb);
    if (j == N) break;
    E += m_c_ * temperature(U, j);
    if (rough()) E += 0.5 * m_c_ * rotationalTemperature(U, j);
  }
  return E + contactEnergy(U[heightIndex(0)]) + contactEnergy(g_.height - U[heightIndex(N)]);
}

double GranularHydro1D::contactEnergy(double gap) const {
  if (hardWalls()) return 0;  // a hard wall stores nothing
  return wallContactEnergy(gap, model_.sigma, reg_.contact_scale, numerics_);
}

void GranularHydro1D::wallEvents(double t, const double* U, WallHold hold, double* g) const {
  const int N = g_.cells;
  // Called after every step and in the root search: only the two wall cells are evaluated.
  if (hold.plate || hold.lid) {
    cellState(U, 0, *values_);
    cellState(U, N - 1, *values_);
  }
  const auto [plate, lid] =
      hold.plate || hold.lid ? wallReactions(t, *values_) : std::pair<double, double>{0, 0};
  // A free node's root is at 1e-9 sigma past its wall, not at it: a node released at the wall
  // starts with a non-zero function, which CVODE would otherwise hold inactive until it moves
  // and so miss its return (the landing resets it to the wall).
  const double past = 1e-9 * model_.sigma;
  g[0] = hold.plate ? plate : U[heightIndex(0)] + past;
  g[1] = hold.lid ? lid : g_.height - U[heightIndex(N)] + past;
}

GranularHydro1D::WallHold GranularHydro1D::wallEvent(double t, std::vector<double>& U,
                                                     WallHold hold,
                                                     const std::vector<int>& found) const {
  const int N = g_.cells;
  // The node lands completely inelastically, as the layer does (its particles' bounce is the
  // wall collisions' loss): its kinetic energy relative to the wall (half a cell's mass) heats
  // the wall cell, and the wall's impulse (m_c/2) |u| does the work -(m_c/2) u v_b on it in the
  // lab frame (the plate's work, in the budget), so the lab-frame energy changes by that work.
  const auto land = [&](int node, int cell) {
    const double u = U[velocityIndex(node)];
    const double theta = temperature(U.data(), cell) + 0.25 * u * u;  // 0.5 (m_c/2) u^2 / m_c
    U[temperatureIndex(cell)] = temperatureUnknown(theta);
    if (energy_budget_) U[budgetIndex(0)] -= 0.5 * m_c_ * u * g_.plateVelocity(t);
    U[velocityIndex(node)] = 0;
    U[heightIndex(node)] = node == 0 ? 0.0 : g_.height;
  };
  WallHold next = hold;
  if (found[0] != 0) {
    next.plate = !hold.plate;
    if (next.plate) land(0, 0);
  }
  if (found[1] != 0) {
    next.lid = !hold.lid;
    if (next.lid) land(N, N - 1);
  }
  // A node that lands where its wall would pull on it leaves again at once.
  cellStates(U.data(), *values_);
  const auto [plate, lid] = wallReactions(t, *values_);
  next.plate = next.plate && plate > 0;
  next.lid = next.lid && lid > 0;
  return next;
}

bool GranularHydro1D::withinWalls(const double* U) const {
  if (!hardWalls()) return true;
  const double slack = 1e-6 * model_.sigma;
  return U[heightIndex(0)] >= -slack && U[heightIndex(g_.cells)] <= g_.height + slack;
}

GranularHydro1D::WallHold GranularHydro1D::startingHold(double t, const double* U) const {
  if (!hardWalls()) return {};
  cellStates(U, *values_);
  const auto [plate, lid] = wallReactions(t, *values_);
  const double touch = 1e-12 * model_.sigma;
  return {U[heightIndex(0)] <= touch && plate > 0,
          U[heightIndex(g_.cells)] >= g_.height - touch && lid > 0};
}

GranularHydro1D::CellView GranularHydro1D::cellView(const double* U, int i) const {
  const EffectiveCell<double> c = effectiveCell(reg_, m_c_, theta_unit_, U[heightIndex(i)],
                                                U[heightIndex(i + 1)], U[temperatureIndex(i)]);
  return {c.rho, c.theta};
}

double GranularHydro1D::spacingFor(double rho_eff) const {
  const double y = (reg_.rho_max - rho_eff) / reg_.packing_width;  // s((rho_max - rho)/d) = y
  const double rho = reg_.rho_max - reg_.packing_width * (y - 1 / y);
  const double length = m_c_ / rho, w = reg_.length_floor;
  return length - w * w / (4 * length);  // smoothPositivePart(l, w) = length
}

double GranularHydro1D::effectiveTemperature(double theta) const { return theta + reg_.theta_min; }

int GranularHydro1D::rightHandSide(double t, const double* U, double* dUdt, WallHold hold) const {
  const int status = residual(t, U, dUdt, *values_, hold);
  if (status != 0 || !energy_budget_) return status;
  const EnergyRates r = energyRates(t, U, hold);
  const double rates[kBudgetTerms] = {r.plate_work, r.collisional_loss, r.friction_loss,
                                      r.wall_loss, r.side_wall_loss};
  for (int k = 0; k < kBudgetTerms; ++k) dUdt[budgetIndex(k)] = rates[k];
  return 0;
}

template <int Colours>
int GranularHydro1D::jacobianWith(double t, const double* U, const BandWriter& write,
                                  JetWorkspace<Colours>& j, WallHold hold) const {
  const int n = size(), K = vars_;
  for (int k = 0; k < n; ++k) {
    const int colour = (k / K) % kBlockColours * K + k % K;
    j.U[k] = Jet<Colours>(U[k], Colours, colour);
  }
  if (residual(t, j.U.data(), j.dU.data(), j.w, hold) != 0) return 1;
  for (int k = 0; k < n; ++k)
    if (!j.dU[k].derivatives().allFinite()) return 1;
  for (int col = 0; col < n; ++col) {
    const int block = col / K;
    const int colour = block % kBlockColours * K + col % K;
    const int first = std::max(0, (block - 2) * K), last = std::min(n, (block + 3) * K);
    for (int row = first; row < last; ++row) write(row, col, j.dU[row].derivatives()[colour]);
  }
  return 0;
}

int GranularHydro1D::jacobian(double t, const double* U, const BandWriter& write,
                              WallHold hold) const {
  return rough() ? jacobianWith(t, U, write, *rough_jets_, hold)
                 : jacobianWith(t, U, write, *smooth_jets_, hold);
}

}  // namespace granwave::hydro
