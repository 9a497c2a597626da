// CVODE's vector arithmetic and its dense linear solve done by Eigen.
//
// Why: the project links Debian's STATIC SUNDIALS 6.4 archives (libsundials_cvode.a,
// libsundials_nvecserial.a; CMakeLists.txt says why static), and those are built without
// optimisation (objdump shows every loop variable spilled to the stack; an 8-element axpy takes
// ~200 instructions). Callgrind on model/balanced-4cart.yaml (reduced, accuracy 1e-6): the
// N_Vector operations and the dense LU were ~23 M of the run's ~54 M instructions, more than the
// model's own right-hand side. SUNDIALS lets a program supply vector operations (the N_Vector
// ops table, which CVODE copies into every clone) and a linear solver of its own; these use
// Eigen, compiled with the project's flags. The state has 4-8 entries, so what is saved is call
// and loop overhead, not flops. Results agree with the library's to round-off (the library
// special-cases a = ±1 in z = a·x + b·y; Eigen always multiplies, which is exact for ±1).
#pragma once

#include <nvector/nvector_serial.h>
#include <sundials/sundials_linearsolver.h>

namespace rollerdyn {

// Replaces linear sum, constant, scale and the weighted RMS norm of serial vector v by Eigen
// expressions; call before the vector is cloned (before CVodeInit).
void useEigenVectorOps(N_Vector v);

// A direct linear solver for CVODE's Newton iteration: LU with partial pivoting
// (Eigen::PartialPivLU) of the n x n dense SUNMatrix CVODE passes to setup. Free with
// SUNLinSolFree.
SUNLinearSolver makeEigenDenseSolver(int n, SUNContext ctx);

}  // namespace rollerdyn
