// splinekit — supernodal multifrontal sparse Cholesky factorization A = L Lᵀ.
//
// The linear solver of the bounded biharmonic weights' active-set iterations (box_qp.h,
// subset_solver.h), which factor one principal submatrix of the bilaplacian per iteration. Columns
// with the same structure are grouped into supernodes (fundamental supernodes, then relaxed
// amalgamation that accepts a few explicit zeros for larger blocks); each supernode is factored
// as a dense frontal matrix, and its Schur-complement update is passed to its parent in the
// elimination tree (multifrontal method, Duff & Reid 1983; Liu 1992). Column counts follow
// Gilbert, Ng & Peyton 1994. On the bilaplacian's two-ring stencil this is 2–4× faster than a
// column-by-column factorization (Eigen's SimplicialLLT).
//
// The caller chooses the fill-reducing order: A is factored in the order it is given (then
// postordered along its elimination tree, which leaves the factor's fill unchanged).
#pragma once

#include <Eigen/SparseCore>
#include <cstddef>
#include <vector>

namespace splinekit::skin {

class SupernodalCholesky {
 public:
  // ---- Factorization ----------------------------------------------------------------------------
  // Analyzes and factors A.
  //   A  n by n, symmetric positive definite, both triangles stored, already in elimination order
  // Returns false when a pivot is not positive (A is not numerically positive definite); the
  // factor is then unusable (solve must not be called) until a later factorize succeeds.
  bool factorize(const Eigen::SparseMatrix<double>& A);

  // ---- Queries (after a successful factorize) ---------------------------------------------------
  // Solves A x = b in place.
  //   b  n values in the order of A's rows; overwritten with x
  void solve(double* b) const;

  // The factor L (n by n, lower triangular, with the explicit zeros that amalgamation stored) of
  // P A Pᵀ = L Lᵀ, where P is the postorder: row k of P A Pᵀ is row postorder()[k] of A.
  Eigen::SparseMatrix<double> factor() const;

  // The elimination order of the factor: postorder()[k] = the row of A eliminated k-th (n values).
  const std::vector<int>& postorder() const { return post_; }

  // ---- Counters ---------------------------------------------------------------------------------
  int size() const { return n_; }                                 // n
  int supernode_count() const { return int(first_.size()) - 1; }  // supernodes after amalgamation
  // Columns of supernode s (0 ≤ s < supernode_count()).
  int supernode_columns(int s) const { return first_[s + 1] - first_[s]; }

 private:
  // Elimination tree, postorder, column counts, supernodes and their row structures.
  void analyze(const Eigen::SparseMatrix<double>& A);
  // Assembles and factors each supernode's front; false on a non-positive pivot.
  bool factorize_numeric(const Eigen::SparseMatrix<double>& A);

  int n_ = 0;
  std::vector<int> post_, inverse_post_;  // postorder: column k of the factor is column post_[k] of A
  std::vector<int> parent_;               // elimination tree, postordered numbering
  std::vector<int> first_;                // supernode s = columns [first_[s], first_[s+1])
  std::vector<int> snode_;                // supernode of each column
  std::vector<int> row_ptr_, rows_;       // rows below each supernode (sorted)
  std::vector<size_t> value_ptr_;         // dense (columns + rows) by columns block per supernode
  std::vector<double> values_;
  std::vector<double> front_, stack_;  // numeric workspace, kept across factorizations
};

}  // namespace splinekit::skin
