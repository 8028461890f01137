#include "supernodal_cholesky.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <utility>

namespace splinekit::skin {

using SpMat = Eigen::SparseMatrix<double>;

bool SupernodalCholesky::factorize(const SpMat& A) {
  n_ = int(A.rows());
  analyze(A);
  return factorize_numeric(A);
}

void SupernodalCholesky::solve(double* b) const {
  Eigen::Map<Eigen::VectorXd> x(b, n_);
  // Postordered copy: supernode columns are contiguous there.
  Eigen::VectorXd y(n_), t;
  for (int k = 0; k < n_; ++k) y[k] = x[post_[k]];
  const int S = supernode_count();
  for (int s = 0; s < S; ++s) {  // L y = b
    const int f = first_[s], ns = first_[s + 1] - f, r = row_ptr_[s + 1] - row_ptr_[s];
    const Eigen::Map<const Eigen::MatrixXd> Ls(values_.data() + value_ptr_[s], ns + r, ns);
    auto ys = y.segment(f, ns);
    Ls.topRows(ns).triangularView<Eigen::Lower>().solveInPlace(ys);
    if (r == 0) continue;
    t.noalias() = Ls.bottomRows(r) * ys;
    for (int a = 0; a < r; ++a) y[rows_[row_ptr_[s] + a]] -= t[a];
  }
  for (int s = S - 1; s >= 0; --s) {  // Lᵀ x = y
    const int f = first_[s], ns = first_[s + 1] - f, r = row_ptr_[s + 1] - row_ptr_[s];
    const Eigen::Map<const Eigen::MatrixXd> Ls(values_.data() + value_ptr_[s], ns + r, ns);
    auto ys = y.segment(f, ns);
    if (r > 0) {
      t.resize(r);
      for (int a = 0; a < r; ++a) t[a] = y[rows_[row_ptr_[s] + a]];
      ys.noalias() -= Ls.bottomRows(r).transpose() * t;
    }
    Ls.topRows(ns).transpose().triangularView<Eigen::Upper>().solveInPlace(ys);
  }
  for (int k = 0; k < n_; ++k) x[post_[k]] = y[k];
}

void SupernodalCholesky::analyze(const SpMat& A) {
  const int n = n_;
  // Elimination tree (Liu's algorithm with path compression).
  std::vector<int> parent(size_t(n), -1), ancestor(size_t(n), -1);
  for (int k = 0; k < n; ++k)
    for (SpMat::InnerIterator it(A, k); it; ++it)
      for (int i = int(it.row()); i != -1 && i < k;) {
        const int next = ancestor[i];
        ancestor[i] = k;
        if (next == -1) parent[i] = k;
        i = next;
      }
  // Postorder (children before parents, each subtree contiguous), iterative DFS.
  std::vector<int> head(size_t(n), -1), sibling(size_t(n), -1), stack;
  for (int j = n - 1; j >= 0; --j)
    if (parent[j] != -1) sibling[j] = head[parent[j]], head[parent[j]] = j;
  post_.clear();
  for (int root = 0; root < n; ++root) {
    if (parent[root] != -1) continue;
    stack.push_back(root);
    while (!stack.empty()) {
      const int p = stack.back(), c = head[p];
      if (c == -1) {
        stack.pop_back();
        post_.push_back(p);
      } else {
        head[p] = sibling[c];
        stack.push_back(c);
      }
    }
  }
  inverse_post_.resize(size_t(n));
  for (int k = 0; k < n; ++k) inverse_post_[post_[k]] = k;
  parent_.assign(size_t(n), -1);
  for (int j = 0; j < n; ++j)
    if (parent[j] != -1) parent_[inverse_post_[j]] = inverse_post_[parent[j]];
  // Column counts of L (Gilbert, Ng & Peyton 1994), in O(nnz(A)·α): row i of L is the union of
  // the tree paths from each k < i with A_ik ≠ 0 up to i (its row subtree). Walking postordered
  // columns, each column j adds 1 per row subtree in which it is a leaf and subtracts 1 at the
  // least common ancestor of consecutive leaves (found by path-compressed ancestor links);
  // summing these deltas over subtrees gives the counts.
  std::vector<int> count(size_t(n), 0), first_descendant(size_t(n), -1), max_first(size_t(n), -1);
  std::vector<int> previous_leaf(size_t(n), -1), link(size_t(n), 0), children(size_t(n), 0);
  for (int k = 0; k < n; ++k) {
    count[k] = first_descendant[k] == -1 ? 1 : 0;  // a leaf of the elimination tree
    for (int j = k; j != -1 && first_descendant[j] == -1; j = parent_[j]) first_descendant[j] = k;
    link[k] = k;
  }
  for (int j = 0; j < n; ++j) {
    if (parent_[j] != -1) --count[parent_[j]];
    for (SpMat::InnerIterator it(A, post_[j]); it; ++it) {
      const int i = inverse_post_[it.row()];
      if (i <= j || first_descendant[j] <= max_first[i]) continue;  // j is not a leaf of row subtree i
      max_first[i] = first_descendant[j];
      const int previous = previous_leaf[i];
      previous_leaf[i] = j;
      ++count[j];
      if (previous == -1) continue;  // the first leaf
      int q = previous;
      while (q != link[q]) q = link[q];
      for (int s = previous; s != q;) {
        const int up = link[s];
        link[s] = q;
        s = up;
      }
      --count[q];  // q = the least common ancestor of the two leaves
    }
    if (parent_[j] != -1) link[j] = parent_[j];
  }
  for (int j = 0; j < n; ++j)
    if (parent_[j] != -1) count[parent_[j]] += count[j];
  for (int j = 0; j < n; ++j)
    if (parent_[j] != -1) ++children[parent_[j]];
  // Fundamental supernodes: j joins j−1 when j−1's only parent is j, j has no other child,
  // and their structures agree.
  std::vector<int> first, size;  // first column and front size (rows incl. own columns) per supernode
  for (int j = 0; j < n; ++j)
    if (!(j > 0 && parent_[j - 1] == j && children[j] == 1 && count[j - 1] == count[j] + 1)) {
      first.push_back(j);
      size.push_back(count[j]);
    }
  // Relaxed amalgamation: absorb the child supernode that ends right before s (its structure
  // is contained in s's front) when the explicit zeros this adds stay a small fraction.
  const int S0 = int(first.size());
  std::vector<int> last(static_cast<size_t>(S0)), alive(size_t(S0), 1), ending_at(size_t(n), -1);
  std::vector<double> zeros(size_t(S0), 0.0);
  for (int s = 0; s < S0; ++s) last[s] = (s + 1 < S0 ? first[s + 1] : n) - 1;
  auto stored = [](double columns, double rows) { return columns * rows - columns * (columns - 1) / 2; };
  for (int s = 0; s < S0; ++s) {
    while (first[s] > 0) {
      const int c = ending_at[first[s] - 1];
      if (c < 0 || parent_[last[c]] < first[s] || parent_[last[c]] > last[s]) break;  // not a child of s
      const int nc = last[c] - first[c] + 1, ns = last[s] - first[s] + 1, m = nc + size[s];
      const double z = zeros[c] + zeros[s] + stored(nc + ns, m) - stored(nc, size[c]) - stored(ns, size[s]);
      const double fraction = z / stored(nc + ns, m);
      const int columns = nc + ns;
      if (!(columns <= 4 || (columns <= 16 && fraction < 0.8) || (columns <= 48 && fraction < 0.1) || fraction < 0.05))
        break;
      alive[c] = 0;
      first[s] = first[c];
      size[s] = m;
      zeros[s] = z;
    }
    ending_at[last[s]] = s;
  }
  first_.clear();
  row_ptr_.assign(1, 0);
  for (int s = 0; s < S0; ++s)
    if (alive[s]) {
      first_.push_back(first[s]);
      row_ptr_.push_back(row_ptr_.back() + size[s] - (last[s] - first[s] + 1));
    }
  first_.push_back(n);
  const int S = supernode_count();
  snode_.resize(size_t(n));
  for (int s = 0; s < S; ++s)
    for (int j = first_[s]; j < first_[s + 1]; ++j) snode_[j] = s;
  // Row structure below each supernode: its columns' entries of A and its children's rows,
  // restricted to rows past the supernode (sorted, so fronts nest in increasing order).
  rows_.resize(size_t(row_ptr_[S]));
  std::vector<int> child_head(size_t(S), -1), child_next(size_t(S), -1);
  for (int s = S - 1; s >= 0; --s) {
    const int p = parent_[first_[s + 1] - 1];
    if (p != -1) child_next[s] = child_head[snode_[p]], child_head[snode_[p]] = s;
  }
  std::vector<int> mark(static_cast<size_t>(n), -1);
  for (int s = 0; s < S; ++s) {
    const int l = first_[s + 1] - 1;
    int at = row_ptr_[s];
    auto add = [&](int i) {
      if (i > l && mark[i] != s) mark[i] = s, rows_[at++] = i;
    };
    for (int j = first_[s]; j <= l; ++j)
      for (SpMat::InnerIterator it(A, post_[j]); it; ++it) add(inverse_post_[it.row()]);
    for (int c = child_head[s]; c != -1; c = child_next[c])
      for (int e = row_ptr_[c]; e < row_ptr_[c + 1]; ++e) add(rows_[e]);
    std::sort(rows_.begin() + row_ptr_[s], rows_.begin() + at);
  }
}

bool SupernodalCholesky::factorize_numeric(const SpMat& A) {
  const int S = supernode_count();
  value_ptr_.assign(size_t(S) + 1, 0);
  int largest = 0;
  for (int s = 0; s < S; ++s) {
    const int ns = first_[s + 1] - first_[s], m = ns + row_ptr_[s + 1] - row_ptr_[s];
    value_ptr_[s + 1] = value_ptr_[s] + size_t(m) * ns;
    largest = std::max(largest, m);
  }
  values_.resize(value_ptr_[S]);
  // Workspace kept across factorizations (grown, never shrunk): the front, and a stack of the
  // update matrices not yet consumed by their parents.
  if (front_.size() < size_t(largest) * largest) front_.resize(size_t(largest) * largest);
  size_t top = 0;
  std::vector<std::pair<size_t, int>> pending;       // (offset in stack_, supernode) of each pending update
  std::vector<int> position(size_t(n_), -1), local;  // front position of each row; of a child's rows
  for (int s = 0; s < S; ++s) {
    const int f = first_[s], ns = first_[s + 1] - f, r = row_ptr_[s + 1] - row_ptr_[s], m = ns + r;
    const int* rows = rows_.data() + row_ptr_[s];
    for (int a = 0; a < ns; ++a) position[f + a] = a;
    for (int a = 0; a < r; ++a) position[rows[a]] = ns + a;
    // Assemble the front (lower triangle): A's columns, then the children's updates, which in
    // postorder are the most recent pending ones.
    Eigen::Map<Eigen::MatrixXd> F(front_.data(), m, m);
    for (int a = 0; a < m; ++a) F.col(a).tail(m - a).setZero();
    for (int a = 0; a < ns; ++a)
      for (SpMat::InnerIterator it(A, post_[f + a]); it; ++it) {
        const int i = inverse_post_[it.row()];
        if (i >= f + a) F(position[i], a) += it.value();
      }
    while (!pending.empty() && snode_[parent_[first_[pending.back().second + 1] - 1]] == s) {
      const auto [offset, c] = pending.back();
      pending.pop_back();
      const int rc = row_ptr_[c + 1] - row_ptr_[c];
      local.resize(size_t(rc));
      for (int a = 0; a < rc; ++a) local[a] = position[rows_[row_ptr_[c] + a]];
      const Eigen::Map<const Eigen::MatrixXd> U(stack_.data() + offset, rc, rc);
      for (int b = 0; b < rc; ++b) {
        double* column = &F(0, local[b]);
        for (int a = b; a < rc; ++a) column[local[a]] += U(a, b);
      }
      top = offset;
    }
    // Dense partial factorization: F11 = L11 L11ᵀ, L21 = F21 L11⁻ᵀ, update F22 − L21 L21ᵀ.
    auto F11 = F.topLeftCorner(ns, ns);
    Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>> llt(F11);
    if (llt.info() != Eigen::Success) return false;
    if (r > 0) {
      auto F21 = F.bottomLeftCorner(r, ns);
      F11.triangularView<Eigen::Lower>().transpose().solveInPlace<Eigen::OnTheRight>(F21);
      auto F22 = F.bottomRightCorner(r, r);
      F22.selfadjointView<Eigen::Lower>().rankUpdate(F21, -1.0);
      const size_t offset = top;
      top += size_t(r) * r;
      if (stack_.size() < top) stack_.resize(top);
      Eigen::Map<Eigen::MatrixXd> U(stack_.data() + offset, r, r);
      for (int b = 0; b < r; ++b) U.col(b).tail(r - b) = F22.col(b).tail(r - b);  // lower triangle only
      pending.emplace_back(offset, s);
    }
    Eigen::Map<Eigen::MatrixXd>(values_.data() + value_ptr_[s], m, ns) = F.leftCols(ns);
  }
  return true;
}

SpMat SupernodalCholesky::factor() const {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(values_.size());
  for (int s = 0; s < supernode_count(); ++s) {
    const int f = first_[s], ns = first_[s + 1] - f, r = row_ptr_[s + 1] - row_ptr_[s];
    const Eigen::Map<const Eigen::MatrixXd> Ls(values_.data() + value_ptr_[s], ns + r, ns);
    for (int b = 0; b < ns; ++b) {
      for (int a = b; a < ns; ++a) entries.emplace_back(f + a, f + b, Ls(a, b));
      for (int a = 0; a < r; ++a) entries.emplace_back(rows_[row_ptr_[s] + a], f + b, Ls(ns + a, b));
    }
  }
  SpMat L(n_, n_);
  L.setFromTriplets(entries.begin(), entries.end());
  return L;
}

}  // namespace splinekit::skin
