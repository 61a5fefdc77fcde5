#pragma once
// LU factorisation with partial pivoting of a band matrix, and the solve with its factors, in
// LAPACK's band storage (the algorithm of LAPACK's dgbtf2 and dgbtrs, which is also
// SUNDIALS's): column j of A holds A(i, j) at ab[j * ldab + kl + ku + i - j] for
// j - ku <= i <= j + kl, and the first kl rows of each column are room for the fill-in of the
// row interchanges (ldab >= 2 kl + ku + 1). SUNDIALS's band matrix has exactly this layout
// (its "stored upper bandwidth" is kl + ku).
//
// Why not LAPACK itself: at the continuum's bandwidth (kl = ku = 8 to 11) dgbtf2 and dgbtrs
// make one BLAS call per column (idamax, dswap, dscal, dger; dger again in the solve) for
// 8 to 11 multiply-adds each; with Debian's reference BLAS the calls cost more than the
// arithmetic, and the solve took 4x the instructions of these loops (docs/performance.md).

namespace granwave::hydro {

// Factors A = P L U in place. pivots[j] = the row swapped with row j at step j. Returns 0, or
// j + 1 for the first column j whose pivot is exactly zero (the factorisation is then
// unusable; LAPACK's INFO convention).
int bandLuFactor(double* ab, int ldab, int n, int kl, int ku, int* pivots);

// Solves A x = b with the factors of bandLuFactor; b is overwritten by x.
void bandLuSolve(const double* ab, int ldab, int n, int kl, int ku, const int* pivots, double* b);

}  // namespace granwave::hydro
