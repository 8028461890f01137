// splinekit — factorizations of the principal submatrices Q_II of one fixed sparse SPD matrix Q,
// for index sets I that change from call to call (the free set of an active-set method).
//
// The fill-reducing ordering (AMD) is computed once for all of Q: restricting an elimination
// order to a subset of the variables is an elimination order of the induced subgraph, so no new
// ordering is needed per set. Each factorization is a SupernodalCholesky.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "skin/supernodal_cholesky.h"

namespace splinekit::skin {

class SubsetSolver {
 public:
  // ---- Constructors -----------------------------------------------------------------------------
  //   Q  n by n, symmetric positive definite, both triangles stored. Kept by reference: it must
  //      outlive the solver.
  explicit SubsetSolver(const Eigen::SparseMatrix<double>& Q);

  // ---- Mutators ---------------------------------------------------------------------------------
  // Factorizes Q_II for I = {i : keep[i]}.
  //   keep  n flags
  // Returns false if Q_II is not numerically positive definite.
  bool factorize(const std::vector<char>& keep);

  // ---- Queries ----------------------------------------------------------------------------------
  // x_I = Q_II⁻¹ rhs_I for the last factorized I.
  //   rhs  n values (only those in I are read)
  //   x    n values; those in I are overwritten, the others are left untouched
  void solve(const Eigen::VectorXd& rhs, Eigen::VectorXd& x);

 private:
  const Eigen::SparseMatrix<double>& Q_;
  std::vector<int> order_;  // order_[k] = the variable of Q eliminated k-th (AMD)
  std::vector<int> local_;  // local_[v] = v's index in Q_II, or −1 when v ∉ I
  std::vector<int> vars_;   // the variables of I in elimination order
  Eigen::SparseMatrix<double> sub_;
  SupernodalCholesky cholesky_;
  Eigen::VectorXd b_;
};

}  // namespace splinekit::skin
