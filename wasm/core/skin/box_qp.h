// splinekit — the box-constrained convex quadratic program of one bounded biharmonic weight:
//
//   minimize ½ xᵀQx + cᵀx  subject to  0 ≤ x ≤ 1,
//
// by the primal-dual active-set method (Hintermüller, Ito & Kunisch 2002) with releases spread
// over neighbouring rings of the active set and an anti-cycling rule (see box_qp.cpp). Each
// iteration fixes the active variables at their bounds and solves for the rest with a
// SubsetSolver (one SupernodalCholesky of Q's free block, in one fill-reducing order).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <string>

#include "skin/subset_solver.h"

namespace splinekit::skin {

struct BoxQpOptions {
  int max_iterations = 100;       // cap on linear solves, including the unconstrained one
  double bound_tolerance = 1e-9;  // how far x may leave [0,1] and still count as feasible
};

// What solve_box_qp did.
struct BoxQpReport {
  int solves = 1;          // linear solves, including the unconstrained one
  bool converged = false;  // the active sets settled within max_iterations
  int pinned = 0;          // variables kept at a bound by the anti-cycling rule
  std::string error;       // "" unless a free block was not numerically positive definite
};

// Minimizes ½ xᵀQx + cᵀx subject to 0 ≤ x ≤ 1. With g = Qx + c, the KKT conditions are: g_i = 0
// where 0 < x_i < 1, g_i ≥ 0 where x_i = 0, g_i ≤ 0 where x_i = 1; a bound stays active while its
// multiplier is wrong-signed by at most the variable's tolerance.
//   Q                     n by n, symmetric positive definite, both triangles stored
//   c                     n
//   multiplier_tolerance  n, ≥ 0: how wrong-signed g_i may be and still keep bound i active
//   options               see BoxQpOptions
//   solver                a SubsetSolver of Q (refactored for every active set)
//   x                     in: the unconstrained minimizer (Q x = −c); out: the solution, clamped
//                         to [0,1] exactly (n values)
BoxQpReport solve_box_qp(const Eigen::SparseMatrix<double>& Q, const Eigen::VectorXd& c,
                         const Eigen::VectorXd& multiplier_tolerance, const BoxQpOptions& options, SubsetSolver& solver,
                         Eigen::VectorXd& x);

}  // namespace splinekit::skin
