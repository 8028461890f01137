#include "subset_solver.h"

#include <Eigen/OrderingMethods>
#include <algorithm>

namespace splinekit::skin {

using SpMat = Eigen::SparseMatrix<double>;

SubsetSolver::SubsetSolver(const SpMat& Q) : Q_(Q), local_(size_t(Q.rows()), -1) {
  Eigen::AMDOrdering<int> amd;
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> order;
  amd(Q_, order);  // order.indices()[k] = the variable eliminated k-th
  order_.assign(order.indices().data(), order.indices().data() + order.size());
}

bool SubsetSolver::factorize(const std::vector<char>& keep) {
  vars_.clear();
  for (int v : order_) {
    local_[v] = keep[v] ? int(vars_.size()) : -1;
    if (keep[v]) vars_.push_back(v);
  }
  // Both triangles of Q_II in elimination order (compressed, column-major).
  const int n = int(vars_.size());
  std::vector<int> outer(size_t(n) + 1, 0);
  for (int c = 0; c < n; ++c) {
    int count = 0;
    for (SpMat::InnerIterator it(Q_, vars_[c]); it; ++it) count += local_[it.row()] >= 0;
    outer[c + 1] = outer[c] + count;
  }
  sub_.resize(n, n);
  sub_.resizeNonZeros(outer[n]);
  std::copy(outer.begin(), outer.end(), sub_.outerIndexPtr());
  for (int c = 0; c < n; ++c) {
    int at = outer[c];
    for (SpMat::InnerIterator it(Q_, vars_[c]); it; ++it)
      if (local_[it.row()] >= 0) {
        sub_.innerIndexPtr()[at] = local_[it.row()];
        sub_.valuePtr()[at++] = it.value();
      }
  }
  return cholesky_.factorize(sub_);
}

void SubsetSolver::solve(const Eigen::VectorXd& rhs, Eigen::VectorXd& x) {
  const int n = int(vars_.size());
  b_.resize(n);
  for (int c = 0; c < n; ++c) b_[c] = rhs[vars_[c]];
  cholesky_.solve(b_.data());
  for (int c = 0; c < n; ++c) x[vars_[c]] = b_[c];
}

}  // namespace splinekit::skin
