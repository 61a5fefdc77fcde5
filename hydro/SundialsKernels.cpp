#include "hydro/SundialsKernels.hpp"

#include <nvector/nvector_serial.h>
#include <sunmatrix/sunmatrix_band.h>

#include <algorithm>
#include <cmath>
#include <new>
#include <vector>

#include "hydro/BandLu.hpp"

namespace granwave::hydro {

namespace {

// --- serial vector: the arithmetic of nvector_serial.c, element by element in its order ---

double* data(N_Vector v) { return NV_DATA_S(v); }
sunindextype length(N_Vector v) { return NV_LENGTH_S(v); }

// z = a x + b y. SUNDIALS's special cases all give a x + b y exactly, except a = b
// (a (x + y)) and a = -b (a (x - y)), which it computes so and so do we.
void linearSum(realtype a, N_Vector x, realtype b, N_Vector y, N_Vector z) {
  const double *xd = data(x), *yd = data(y);
  double* zd = data(z);
  const sunindextype n = length(x);
  if (a == b) {
    for (sunindextype i = 0; i < n; ++i) zd[i] = a * (xd[i] + yd[i]);
  } else if (a == -b) {
    for (sunindextype i = 0; i < n; ++i) zd[i] = a * (xd[i] - yd[i]);
  } else {
    for (sunindextype i = 0; i < n; ++i) zd[i] = a * xd[i] + b * yd[i];
  }
}

void constant(realtype c, N_Vector z) { std::fill(data(z), data(z) + length(z), c); }

template <class F>
void map(N_Vector x, N_Vector z, F f) {
  const double* xd = data(x);
  double* zd = data(z);
  for (sunindextype i = 0, n = length(x); i < n; ++i) zd[i] = f(xd[i]);
}

template <class F>
void map2(N_Vector x, N_Vector y, N_Vector z, F f) {
  const double *xd = data(x), *yd = data(y);
  double* zd = data(z);
  for (sunindextype i = 0, n = length(x); i < n; ++i) zd[i] = f(xd[i], yd[i]);
}

void product(N_Vector x, N_Vector y, N_Vector z) {
  map2(x, y, z, [](double a, double b) { return a * b; });
}
void quotient(N_Vector x, N_Vector y, N_Vector z) {
  map2(x, y, z, [](double a, double b) { return a / b; });
}
void scale(realtype c, N_Vector x, N_Vector z) {
  map(x, z, [c](double a) { return c * a; });
}
void absolute(N_Vector x, N_Vector z) {
  map(x, z, [](double a) { return std::abs(a); });
}
void inverse(N_Vector x, N_Vector z) {
  map(x, z, [](double a) { return 1.0 / a; });
}
void addConstant(N_Vector x, realtype b, N_Vector z) {
  map(x, z, [b](double a) { return a + b; });
}
void compare(realtype c, N_Vector x, N_Vector z) {
  map(x, z, [c](double a) { return std::abs(a) >= c ? 1.0 : 0.0; });
}

realtype dotProduct(N_Vector x, N_Vector y) {
  const double *xd = data(x), *yd = data(y);
  double sum = 0;
  for (sunindextype i = 0, n = length(x); i < n; ++i) sum += xd[i] * yd[i];
  return sum;
}

realtype maxNorm(N_Vector x) {
  const double* xd = data(x);
  double largest = 0;
  for (sunindextype i = 0, n = length(x); i < n; ++i)
    if (std::abs(xd[i]) > largest) largest = std::abs(xd[i]);
  return largest;
}

realtype weightedSquareSum(N_Vector x, N_Vector w) {
  const double *xd = data(x), *wd = data(w);
  double sum = 0;
  for (sunindextype i = 0, n = length(x); i < n; ++i) {
    const double p = xd[i] * wd[i];
    sum += p * p;
  }
  return sum;
}

realtype weightedSquareSumMasked(N_Vector x, N_Vector w, N_Vector id) {
  const double *xd = data(x), *wd = data(w), *md = data(id);
  double sum = 0;
  for (sunindextype i = 0, n = length(x); i < n; ++i)
    if (md[i] > 0.0) {
      const double p = xd[i] * wd[i];
      sum += p * p;
    }
  return sum;
}

realtype wrmsNorm(N_Vector x, N_Vector w) {
  return std::sqrt(weightedSquareSum(x, w) / static_cast<double>(length(x)));
}
realtype wrmsNormMasked(N_Vector x, N_Vector w, N_Vector id) {
  return std::sqrt(weightedSquareSumMasked(x, w, id) / static_cast<double>(length(x)));
}
realtype weightedL2Norm(N_Vector x, N_Vector w) { return std::sqrt(weightedSquareSum(x, w)); }

realtype minimum(N_Vector x) {
  const double* xd = data(x);
  double smallest = xd[0];
  for (sunindextype i = 1, n = length(x); i < n; ++i)
    if (xd[i] < smallest) smallest = xd[i];
  return smallest;
}

realtype l1Norm(N_Vector x) {
  const double* xd = data(x);
  double sum = 0;
  for (sunindextype i = 0, n = length(x); i < n; ++i) sum += std::abs(xd[i]);
  return sum;
}

booleantype inverseTest(N_Vector x, N_Vector z) {
  const double* xd = data(x);
  double* zd = data(z);
  bool no_zero = true;
  for (sunindextype i = 0, n = length(x); i < n; ++i) {
    if (xd[i] == 0.0)
      no_zero = false;
    else
      zd[i] = 1.0 / xd[i];
  }
  return no_zero ? SUNTRUE : SUNFALSE;
}

// m_i = 1 where x_i violates constraint c_i (|c| > 1.5: x c > 0; |c| > 0.5: x c >= 0; other
// c: none), else 0; true if none is violated.
booleantype constraintMask(N_Vector c, N_Vector x, N_Vector m) {
  const double *cd = data(c), *xd = data(x);
  double* md = data(m);
  bool satisfied = true;
  for (sunindextype i = 0, n = length(x); i < n; ++i) {
    md[i] = 0.0;
    if (cd[i] == 0.0) continue;
    const double p = xd[i] * cd[i];
    if ((std::abs(cd[i]) > 1.5 && p <= 0.0) || (std::abs(cd[i]) > 0.5 && p < 0.0)) {
      md[i] = 1.0;
      satisfied = false;
    }
  }
  return satisfied ? SUNTRUE : SUNFALSE;
}

// min over denominators != 0 of num/den; BIG_REAL if there is none.
realtype minQuotient(N_Vector num, N_Vector den) {
  const double *nd = data(num), *dd = data(den);
  bool first = true;
  double smallest = BIG_REAL;
  for (sunindextype i = 0, n = length(num); i < n; ++i) {
    if (dd[i] == 0.0) continue;
    const double q = nd[i] / dd[i];
    if (first) {
      smallest = q;
      first = false;
    } else if (!(smallest < q)) {  // SUNMIN(min, q)
      smallest = q;
    }
  }
  return smallest;
}

// z = sum_j c_j X_j (X_0 may be z), summed in j's order per element as SUNDIALS does.
int linearCombination(int count, realtype* c, N_Vector* X, N_Vector z) {
  scale(c[0], X[0], z);
  double* zd = data(z);
  for (int j = 1; j < count; ++j) {
    const double* xd = data(X[j]);
    const double cj = c[j];
    for (sunindextype i = 0, n = length(z); i < n; ++i) zd[i] += cj * xd[i];
  }
  return 0;
}

// Z_j = a_j x + Y_j.
int scaleAddMulti(int count, realtype* a, N_Vector x, N_Vector* Y, N_Vector* Z) {
  for (int j = 0; j < count; ++j) linearSum(a[j], x, 1.0, Y[j], Z[j]);
  return 0;
}

int dotProductMulti(int count, N_Vector x, N_Vector* Y, realtype* products) {
  for (int j = 0; j < count; ++j) products[j] = dotProduct(x, Y[j]);
  return 0;
}

// --- band matrix ---------------------------------------------------------------------------

int zeroMatrix(SUNMatrix A) {
  std::fill(SM_DATA_B(A), SM_DATA_B(A) + SM_LDATA_B(A), 0.0);
  return SUNMAT_SUCCESS;
}

bool sameShape(SUNMatrix A, SUNMatrix B) {
  return SM_COLUMNS_B(A) == SM_COLUMNS_B(B) && SM_UBAND_B(A) == SM_UBAND_B(B) &&
         SM_LBAND_B(A) == SM_LBAND_B(B) && SM_LDIM_B(A) == SM_LDIM_B(B);
}

// B = A on the band (the fill-in rows are scratch of the factorisation).
int copyMatrix(SUNMatrix A, SUNMatrix B) {
  if (!sameShape(A, B)) return SUNMatCopy_Band(A, B);
  const sunindextype ld = SM_LDIM_B(A), su = SM_SUBAND_B(A), mu = SM_UBAND_B(A);
  const sunindextype ml = SM_LBAND_B(A);
  for (sunindextype j = 0; j < SM_COLUMNS_B(A); ++j) {
    const double* a = SM_DATA_B(A) + j * ld + su - mu;
    std::copy(a, a + mu + ml + 1, SM_DATA_B(B) + j * ld + su - mu);
  }
  return SUNMAT_SUCCESS;
}

// A = c A + I on the band.
int scaleAddIdentity(realtype c, SUNMatrix A) {
  const sunindextype ld = SM_LDIM_B(A), su = SM_SUBAND_B(A), mu = SM_UBAND_B(A);
  const sunindextype ml = SM_LBAND_B(A);
  for (sunindextype j = 0; j < SM_COLUMNS_B(A); ++j) {
    double* a = SM_DATA_B(A) + j * ld + su;  // a[i - j] = A(i, j)
    for (sunindextype k = -mu; k <= ml; ++k) a[k] *= c;
    a[0] += 1.0;
  }
  return SUNMAT_SUCCESS;
}

SUNMatrix cloneMatrix(SUNMatrix A) {
  SUNMatrix B = SUNBandMatrixStorage(SM_COLUMNS_B(A), SM_UBAND_B(A), SM_LBAND_B(A), SM_SUBAND_B(A),
                                     A->sunctx);
  if (B) useCompiledKernels(B);
  return B;
}

// --- band LU solver ------------------------------------------------------------------------

struct BandLuContent {
  std::vector<int> pivots;
  sunindextype last_flag = 0;
};

BandLuContent& content(SUNLinearSolver S) { return *static_cast<BandLuContent*>(S->content); }

SUNLinearSolver_Type solverType(SUNLinearSolver) { return SUNLINEARSOLVER_DIRECT; }
SUNLinearSolver_ID solverId(SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; }
int initialiseSolver(SUNLinearSolver S) {
  content(S).last_flag = 0;
  return SUNLS_SUCCESS;
}

int factor(SUNLinearSolver S, SUNMatrix A) {
  BandLuContent& c = content(S);
  const int n = static_cast<int>(SM_COLUMNS_B(A));
  c.pivots.resize(static_cast<std::size_t>(n));
  const int info =
      bandLuFactor(SM_DATA_B(A), static_cast<int>(SM_LDIM_B(A)), n, static_cast<int>(SM_LBAND_B(A)),
                   static_cast<int>(SM_UBAND_B(A)), c.pivots.data());
  c.last_flag = info;
  return info > 0 ? SUNLS_LUFACT_FAIL : SUNLS_SUCCESS;  // recoverable: CVODE cuts the step
}

int solve(SUNLinearSolver S, SUNMatrix A, N_Vector x, N_Vector b, realtype) {
  const sunindextype n = SM_COLUMNS_B(A);
  if (x != b) std::copy(data(b), data(b) + n, data(x));
  bandLuSolve(SM_DATA_B(A), static_cast<int>(SM_LDIM_B(A)), static_cast<int>(n),
              static_cast<int>(SM_LBAND_B(A)), static_cast<int>(SM_UBAND_B(A)),
              content(S).pivots.data(), data(x));
  content(S).last_flag = 0;
  return SUNLS_SUCCESS;
}

sunindextype lastFlag(SUNLinearSolver S) { return content(S).last_flag; }

int freeSolver(SUNLinearSolver S) {
  if (!S) return SUNLS_SUCCESS;
  delete static_cast<BandLuContent*>(S->content);
  S->content = nullptr;
  SUNLinSolFreeEmpty(S);
  return SUNLS_SUCCESS;
}

}  // namespace

void useCompiledKernels(N_Vector v) {
  N_Vector_Ops o = v->ops;
  o->nvlinearsum = linearSum;
  o->nvconst = constant;
  o->nvprod = product;
  o->nvdiv = quotient;
  o->nvscale = scale;
  o->nvabs = absolute;
  o->nvinv = inverse;
  o->nvaddconst = addConstant;
  o->nvdotprod = dotProduct;
  o->nvmaxnorm = maxNorm;
  o->nvwrmsnorm = wrmsNorm;
  o->nvwrmsnormmask = wrmsNormMasked;
  o->nvmin = minimum;
  o->nvwl2norm = weightedL2Norm;
  o->nvl1norm = l1Norm;
  o->nvcompare = compare;
  o->nvinvtest = inverseTest;
  o->nvconstrmask = constraintMask;
  o->nvminquotient = minQuotient;
  o->nvlinearcombination = linearCombination;
  o->nvscaleaddmulti = scaleAddMulti;
  o->nvdotprodmulti = dotProductMulti;
  // One process holds the whole vector: the local reductions are the global ones.
  o->nvdotprodlocal = dotProduct;
  o->nvmaxnormlocal = maxNorm;
  o->nvminlocal = minimum;
  o->nvl1normlocal = l1Norm;
  o->nvinvtestlocal = inverseTest;
  o->nvconstrmasklocal = constraintMask;
  o->nvminquotientlocal = minQuotient;
  o->nvwsqrsumlocal = weightedSquareSum;
  o->nvwsqrsummasklocal = weightedSquareSumMasked;
}

void useCompiledKernels(SUNMatrix A) {
  A->ops->zero = zeroMatrix;
  A->ops->copy = copyMatrix;
  A->ops->scaleaddi = scaleAddIdentity;
  A->ops->clone = cloneMatrix;
}

SUNLinearSolver bandLuSolver(SUNMatrix A, SUNContext ctx) {
  if (!A || SUNMatGetID(A) != SUNMATRIX_BAND || SM_SUBAND_B(A) != SM_UBAND_B(A) + SM_LBAND_B(A))
    return nullptr;
  SUNLinearSolver S = SUNLinSolNewEmpty(ctx);
  if (!S) return nullptr;
  S->ops->gettype = solverType;
  S->ops->getid = solverId;
  S->ops->initialize = initialiseSolver;
  S->ops->setup = factor;
  S->ops->solve = solve;
  S->ops->lastflag = lastFlag;
  S->ops->free = freeSolver;
  S->content = new (std::nothrow) BandLuContent;
  if (!S->content) {
    SUNLinSolFreeEmpty(S);
    return nullptr;
  }
  return S;
}

}  // namespace granwave::hydro
