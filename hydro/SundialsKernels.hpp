#pragma once
// Compiled replacements for the kernels of Debian 12's SUNDIALS 6.4.1 that CVODE's banded
// Newton solve spends its time in (docs/hydro.md, "Numerics"). Debian builds SUNDIALS without
// optimisation (-O0: every variable of every loop on the stack), so the serial N_Vector's
// element loops cost ~20 instructions per element and the band LU's back-solve ~185,000
// instructions per solve for the paper's 302 unknowns (callgrind): together more than half of
// the solver's CPU. SUNDIALS dispatches every one of them through a per-object table of
// function pointers, which is the documented way to supply a kernel, so this replaces the
// table entries and nothing else:
//
//  - useCompiledKernels(N_Vector): the serial vector's operations (CVODE's clones copy the
//    table). The same arithmetic in the same order as nvector_serial.c, so results are
//    bit-for-bit those of SUNDIALS's own kernels (tested against them).
//  - useCompiledKernels(SUNMatrix): zero, copy, A = cA + I and clone (so the copy CVODE keeps
//    of the Jacobian, made by SUNMatClone, carries them too) of a band matrix.
//  - bandLuSolver(A): a direct linear solver (SUNLinearSolver) that factors the band matrix in
//    place by LU with partial pivoting (hydro/BandLu.hpp) and back-solves with it: SUNDIALS's
//    band solver, compiled.
//
// Only hydro/CvodeIntegrator.cpp and the tests include this header (it names SUNDIALS types,
// which CvodeIntegrator.hpp keeps out of the project's interface).
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>
#include <sundials/sundials_nvector.h>

namespace granwave::hydro {

// v must be a serial N_Vector (N_VNew_Serial).
void useCompiledKernels(N_Vector v);
// A must be a band SUNMatrix (SUNBandMatrix).
void useCompiledKernels(SUNMatrix A);
// A direct solver for the band matrix A (SUNBandMatrix with storage for the LU's fill-in, as
// SUNBandMatrix(n, mu, ml) makes it); nullptr if out of memory. Freed by SUNLinSolFree.
SUNLinearSolver bandLuSolver(SUNMatrix A, SUNContext ctx);

}  // namespace granwave::hydro
