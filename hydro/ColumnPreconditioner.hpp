#pragma once
// The preconditioner of GranularHydro2D's Newton-Krylov solve: P = I - gamma J_c, J_c the
// exact Jacobian (forward-mode, GranularHydro2D::jacobian) restricted to the elements whose row
// and column lie in one column of the grid, factored column by column by band LU
// (hydro/BandLu.hpp; within a column the Jacobian is banded, half-bandwidth 3 K - 1). The
// stiff parts of the layer are vertical (cells of a tenth of a diameter against columns of
// several: sound, viscosity and conduction across the cells, the wall contacts), so the
// column blocks hold them; GMRES does the coupling between columns (docs/hydro.md, "The 2D
// model", where the measured Krylov iterations per Newton iteration are).
#include <vector>

#include "hydro/CvodeIntegrator.hpp"
#include "hydro/GranularHydro2D.hpp"

namespace granwave::hydro {

class ColumnPreconditioner {
 public:
  explicit ColumnPreconditioner(const GranularHydro2D& op);
  // CVODE's psetup and psolve (CvodeOptions::preconditioner).
  int setup(double t, const double* y, bool jacobian_ok, double gamma, bool& recomputed);
  int solve(const double* r, double* z) const;
  KrylovPreconditioner callbacks();
  long jacobianEvaluations() const { return jacobians_; }

 private:
  int ldab() const { return 3 * band_ + 1; }
  double* jacobianAt(int column) { return jac_.data() + static_cast<long>(column) * n_ * band_w_; }
  const GranularHydro2D& op_;
  int n_, band_, band_w_;    // column size, half-bandwidth, 2 band + 1
  std::vector<double> jac_;  // J_c per column, dense band: [column][col][row - col + band]
  std::vector<double> lu_;   // the factors, LAPACK band storage per column
  std::vector<int> pivots_;
  long jacobians_ = 0;
};

}  // namespace granwave::hydro
