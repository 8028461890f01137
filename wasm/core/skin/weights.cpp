#include "weights.h"

#include <Eigen/Cholesky>
#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

namespace splinekit::skin {

using SpMat = Eigen::SparseMatrix<double>;

namespace {

// Twice the signed area of triangle (a, b, c), each a pointer to x,y.
double cross2(const double* a, const double* b, const double* c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
}

const double* vertex(const MeshView2& m, int v) { return m.vertices + 2 * size_t(v); }
const int32_t* triangle(const MeshView2& m, int t) { return m.triangles + 3 * size_t(t); }

int find_root(std::vector<int>& parent, int v) {
  while (parent[v] != v) v = parent[v] = parent[parent[v]];
  return v;
}

// ---------------------------------------------------------------------------------------------
// Free / handle split of the vertices
// ---------------------------------------------------------------------------------------------

// slot[v] ≥ 0: index of v among the free vertices; slot[v] = −1 − j: v is handle j.
struct Split {
  std::vector<int> free;
  std::vector<int> slot;
};

Split split_vertices(int vertex_count, const int32_t* handles, int handle_count) {
  Split s;
  s.slot.assign(size_t(vertex_count), 0);
  for (int j = 0; j < handle_count; ++j) s.slot[handles[j]] = -1 - j;
  for (int v = 0; v < vertex_count; ++v)
    if (s.slot[v] == 0) {
      s.slot[v] = int(s.free.size());
      s.free.push_back(v);
    }
  return s;
}

// A (#V by #V, symmetric) split into A_ff (free by free, sparse) and A_fh (free by #H, dense).
void split_matrix(const SpMat& A, const Split& s, int handle_count, SpMat& Aff, Eigen::MatrixXd& Afh) {
  const int n = int(s.free.size());
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(size_t(A.nonZeros()));
  Afh.setZero(n, handle_count);
  for (int c = 0; c < A.outerSize(); ++c)
    for (SpMat::InnerIterator it(A, c); it; ++it) {
      const int r = s.slot[it.row()], k = s.slot[c];
      if (r < 0) continue;
      if (k >= 0)
        entries.emplace_back(r, k, it.value());
      else
        Afh(r, -1 - k) += it.value();
    }
  Aff.resize(n, n);
  Aff.setFromTriplets(entries.begin(), entries.end());
}

// Writes column `j` of the #V by #H row-major W: handle rows get δ, free rows get x.
void write_column(const Split& s, int handle_count, int j, const Eigen::VectorXd& x, double* W) {
  for (size_t v = 0; v < s.slot.size(); ++v) {
    const int k = s.slot[v];
    W[v * handle_count + j] = k >= 0 ? x[k] : (-1 - k == j ? 1.0 : 0.0);
  }
}

// ---------------------------------------------------------------------------------------------
// Sparse Cholesky: supernodal, multifrontal
// ---------------------------------------------------------------------------------------------

// LLᵀ of a sparse symmetric positive definite matrix in a given elimination order. Columns with
// the same structure are grouped into supernodes (fundamental supernodes, then relaxed
// amalgamation that accepts a few explicit zeros for larger blocks); each supernode is factored
// as a dense frontal matrix, and its Schur-complement update is passed to its parent in the
// elimination tree (multifrontal method, Duff & Reid 1983; Liu 1992). On the bilaplacian's
// two-ring stencil this is 2–4× faster than a column-by-column factorization, which matters
// because BBW factors one matrix per active-set iteration.
class SupernodalCholesky {
 public:
  // A: both triangles of the matrix, already in elimination order. Returns false when a pivot
  // is not positive (the matrix is not numerically positive definite).
  bool factorize(const SpMat& A) {
    n_ = int(A.rows());
    analyze(A);
    return factorize_numeric(A);
  }

  // Solves A x = b in place (b: n values in the same order as A).
  void solve(double* b) const {
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

 private:
  int supernode_count() const { return int(first_.size()) - 1; }

  // Elimination tree, postorder, column counts, supernodes and their row structures.
  void analyze(const SpMat& A) {
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

  bool factorize_numeric(const SpMat& A) {
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
    std::vector<std::pair<size_t, int>> pending;  // (offset in stack_, supernode) of each pending update
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

  int n_ = 0;
  std::vector<int> post_, inverse_post_;  // postorder: column k of the factor is column post_[k] of A
  std::vector<int> parent_;               // elimination tree, postordered numbering
  std::vector<int> first_;                // supernode s = columns [first_[s], first_[s+1])
  std::vector<int> snode_;                // supernode of each column
  std::vector<int> row_ptr_, rows_;       // rows below each supernode (sorted)
  std::vector<size_t> value_ptr_;         // dense (columns + rows) by columns block per supernode
  std::vector<double> values_;
  std::vector<double> front_, stack_;     // numeric workspace
};

// ---------------------------------------------------------------------------------------------
// The bound-constrained QP of one BBW handle
// ---------------------------------------------------------------------------------------------

// Factorizes principal submatrices Q_II of a fixed SPD matrix Q for changing index sets I, in the
// fill-reducing order computed once for all of Q (restricting an elimination order to a subset of
// the variables is an elimination order of the induced subgraph, so no new ordering is needed).
class SubsetSolver {
 public:
  explicit SubsetSolver(const SpMat& Q) : Q_(Q), local_(size_t(Q.rows()), -1) {
    Eigen::AMDOrdering<int> amd;
    Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> order;
    amd(Q_, order);  // order.indices()[k] = the variable eliminated k-th
    order_.assign(order.indices().data(), order.indices().data() + order.size());
  }

  // Factorizes Q_II for I = {i : keep[i]}. Returns false if Q_II is not numerically SPD.
  bool factorize(const std::vector<char>& keep) {
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

  // x_I = Q_II⁻¹ rhs_I for the last factorized I; rhs and x are full-length (x outside I untouched).
  void solve(const Eigen::VectorXd& rhs, Eigen::VectorXd& x) {
    const int n = int(vars_.size());
    b_.resize(n);
    for (int c = 0; c < n; ++c) b_[c] = rhs[vars_[c]];
    cholesky_.solve(b_.data());
    for (int c = 0; c < n; ++c) x[vars_[c]] = b_[c];
  }

 private:
  const SpMat& Q_;
  std::vector<int> order_, local_, vars_;
  SpMat sub_;
  SupernodalCholesky cholesky_;
  Eigen::VectorXd b_;
};

// Which bound holds a variable (one char per variable).
enum class Bound : char { kFree = 0, kLower = 1, kUpper = 2 };

// Rings (in the graph of Q) of the active set released together with a variable whose
// multiplier says "release" (see solve_box_qp).
constexpr int kInitialSpread = 4;

struct BoxQpReport {
  int solves = 1;          // linear solves, including the unconstrained one
  bool converged = false;  // the active sets settled within max_iterations
  int pinned = 0;          // variables kept at a bound by the anti-cycling rule
  std::string error;
};

// Minimizes ½ xᵀQx + cᵀx subject to 0 ≤ x ≤ 1 by the primal-dual active-set method (PDAS), from
// x (the unconstrained minimizer). With g = Qx + c, the KKT conditions are: g_i = 0 where
// 0 < x_i < 1, g_i ≥ 0 where x_i = 0, g_i ≤ 0 where x_i = 1. Each iteration (1) moves free
// variables that violate a bound onto it and releases bound variables whose multiplier g_i has
// the wrong sign, (2) solves Q_II x_I = −(c_I + Q_IA x_A) with the active ones fixed. It stops
// when the sets no longer change, which is exactly the KKT point (up to the tolerances).
//
// Release acceleration: the multipliers of a biharmonic obstacle problem concentrate on the rim
// of the active set, so plain PDAS learns only about that rim and shrinks an oversized active
// set one ring per iteration. Here a release also frees `spread` rings of the same bound around
// it; a variable freed that way which comes back violated halves `spread` (down to 0 = plain
// PDAS, whose fixed points are the same). This cuts the iterations about in half.
//
// Anti-cycling: Q is not an M-matrix, so PDAS can cycle (a few rim variables released for their
// multipliers, then re-bound because they dip a hair below 0). Once a state repeats, spreading
// stops and a variable that has been released before stays at its bound when asked to leave it
// again, which makes the method terminate; such `pinned` variables keep a wrong-signed
// multiplier, at a weight error of the size of their dip (below 1e-10 where observed).
//
// `multiplier_tolerance`: per-variable tolerance on wrong-signed multipliers (see BbwOptions).
BoxQpReport solve_box_qp(const SpMat& Q, const Eigen::VectorXd& c, const Eigen::VectorXd& multiplier_tolerance,
                         const BbwOptions& options, SubsetSolver& solver, Eigen::VectorXd& x) {
  BoxQpReport report;
  const int n = int(c.size());
  const double tol_x = options.bound_tolerance;
  std::vector<Bound> bound(size_t(n), Bound::kFree), next(size_t(n), Bound::kFree);
  std::vector<char> keep(size_t(n), 1);
  std::vector<char> spread_freed(size_t(n), 0), released(size_t(n), 0), pinned(size_t(n), 0);
  std::vector<int> ring, next_ring;
  std::vector<uint64_t> seen;  // hashes of the active sets so far
  Eigen::VectorXd g = Q * x + c, fixed(n), rhs(n);
  int spread = kInitialSpread;
  bool cycling = false;
  for (;;) {
    for (int i = 0; i < n; ++i)
      if (spread_freed[i] && (x[i] < -tol_x || x[i] > 1 + tol_x)) {
        spread /= 2;
        break;
      }
    // The plain PDAS update.
    ring.clear();
    for (int i = 0; i < n; ++i) {
      Bound b = bound[i];
      if (b == Bound::kFree) {
        b = x[i] < -tol_x ? Bound::kLower : x[i] > 1 + tol_x ? Bound::kUpper : Bound::kFree;
      } else if ((b == Bound::kLower && g[i] < -multiplier_tolerance[i]) || (b == Bound::kUpper && g[i] > multiplier_tolerance[i])) {
        if (!cycling || !released[i])
          b = Bound::kFree;
        else if (!pinned[i])
          pinned[i] = 1, ++report.pinned;
      }
      next[i] = b;
      if (bound[i] != Bound::kFree && b == Bound::kFree) ring.push_back(i);
    }
    // Spread the releases over neighbours held at the same bound.
    std::fill(spread_freed.begin(), spread_freed.end(), 0);
    for (int r = 0; r < spread && !ring.empty(); ++r) {
      next_ring.clear();
      for (int i : ring)
        for (SpMat::InnerIterator it(Q, i); it; ++it) {
          const int j = int(it.row());
          if (next[j] != Bound::kFree && next[j] == bound[j] && bound[j] == bound[i]) {
            next[j] = Bound::kFree;
            spread_freed[j] = 1;
            next_ring.push_back(j);
          }
        }
      ring.swap(next_ring);
    }
    if (next == bound) {
      report.converged = true;
      break;
    }
    for (int i = 0; i < n; ++i) released[i] |= bound[i] != Bound::kFree && next[i] == Bound::kFree;
    bound.swap(next);
    // Each iteration is a function of (active set, spread, spread-freed variables), so a repeated
    // state (FNV-1a hash) is a cycle.
    uint64_t hash = 1469598103934665603ull;
    auto mix = [&hash](uint64_t byte) { hash = (hash ^ byte) * 1099511628211ull; };
    for (int i = 0; i < n; ++i) mix(uint64_t(uint8_t(bound[i])) | uint64_t(spread_freed[i]) << 2);
    mix(uint64_t(spread));
    if (std::find(seen.begin(), seen.end(), hash) != seen.end()) cycling = true, spread = 0;
    seen.push_back(hash);
    if (report.solves >= options.max_iterations) break;
    for (int i = 0; i < n; ++i) {
      keep[i] = bound[i] == Bound::kFree;
      fixed[i] = bound[i] == Bound::kUpper ? 1.0 : 0.0;
    }
    if (!solver.factorize(keep)) {
      report.error = "internal: the bilaplacian of the free vertices is not numerically positive definite";
      break;
    }
    rhs = -(c + Q * fixed);
    x = fixed;
    solver.solve(rhs, x);
    g = Q * x + c;
    ++report.solves;
  }
  x = x.cwiseMax(0.0).cwiseMin(1.0);
  return report;
}

// ---------------------------------------------------------------------------------------------
// Point queries
// ---------------------------------------------------------------------------------------------

// Barycentric coordinates of (x,y) in triangle t (unclamped).
void barycentric(const MeshView2& m, int t, double x, double y, double* b) {
  const int32_t* f = triangle(m, t);
  const double *a = vertex(m, f[0]), *p = vertex(m, f[1]), *q = vertex(m, f[2]);
  const double ux = p[0] - a[0], uy = p[1] - a[1], vx = q[0] - a[0], vy = q[1] - a[1];
  const double wx = x - a[0], wy = y - a[1];
  const double d = ux * vy - vx * uy;
  b[1] = (wx * vy - vx * wy) / d;
  b[2] = (ux * wy - wx * uy) / d;
  b[0] = 1.0 - b[1] - b[2];
}

// Squared distance from (x,y) to triangle t and the barycentric coordinates of the nearest point.
double nearest_on_triangle(const MeshView2& m, int t, double x, double y, double* b) {
  barycentric(m, t, x, y, b);
  if (b[0] >= 0 && b[1] >= 0 && b[2] >= 0) return 0.0;
  // Outside: the nearest point is on one of the edges (k, k+1).
  const int32_t* f = triangle(m, t);
  double best = INFINITY;
  for (int k = 0; k < 3; ++k) {
    const double *p = vertex(m, f[k]), *q = vertex(m, f[(k + 1) % 3]);
    const double ex = q[0] - p[0], ey = q[1] - p[1];
    const double s = std::clamp(((x - p[0]) * ex + (y - p[1]) * ey) / (ex * ex + ey * ey), 0.0, 1.0);
    const double dx = p[0] + s * ex - x, dy = p[1] + s * ey - y, d2 = dx * dx + dy * dy;
    if (d2 < best) {
      best = d2;
      b[k] = 1.0 - s;
      b[(k + 1) % 3] = s;
      b[(k + 2) % 3] = 0.0;
    }
  }
  return best;
}

int cell_index(double v, double origin, double cell, int count) {
  const double i = std::floor((v - origin) / cell);
  return !(i > 0) ? 0 : i >= count ? count - 1 : int(i);  // NaN lands in cell 0
}

// Distance from (x,y) to the cells of ring r and beyond: to the part of the grid outside the block
// of cells within Chebyshev distance r−1 of (ci,cj). INFINITY when no such cell is left.
double ring_distance(const TriangleGrid& g, double x, double y, int ci, int cj, int r) {
  if (r == 0) return 0.0;
  const double gx0 = g.x0, gx1 = g.x0 + g.nx * g.cell, gy0 = g.y0, gy1 = g.y0 + g.ny * g.cell;
  const double bx0 = g.x0 + std::max(0, ci - r + 1) * g.cell, bx1 = g.x0 + std::min(g.nx, ci + r) * g.cell;
  const double by0 = g.y0 + std::max(0, cj - r + 1) * g.cell, by1 = g.y0 + std::min(g.ny, cj + r) * g.cell;
  auto to_rect = [&](double x0, double x1, double y0, double y1) {
    const double dx = std::max({x0 - x, 0.0, x - x1}), dy = std::max({y0 - y, 0.0, y - y1});
    return std::sqrt(dx * dx + dy * dy);
  };
  double d = INFINITY;
  if (bx0 > gx0) d = std::min(d, to_rect(gx0, bx0, gy0, gy1));
  if (bx1 < gx1) d = std::min(d, to_rect(bx1, gx1, gy0, gy1));
  if (by0 > gy0) d = std::min(d, to_rect(gx0, gx1, gy0, by0));
  if (by1 < gy1) d = std::min(d, to_rect(gx0, gx1, by1, gy1));
  return d;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Validation
// ---------------------------------------------------------------------------------------------

std::string validate_weights_input(const MeshView2& m, const int32_t* handles, int handle_count) {
  const int nv = m.vertex_count, nf = m.triangle_count;
  if (nv < 3 || !m.vertices) return "the mesh needs at least 3 vertices, got " + std::to_string(nv);
  if (nf < 1 || !m.triangles) return "the mesh has no triangle";
  for (int v = 0; v < nv; ++v)
    if (!std::isfinite(vertex(m, v)[0]) || !std::isfinite(vertex(m, v)[1]))
      return "vertex " + std::to_string(v) + " has a non-finite coordinate";
  std::vector<int> parent(static_cast<size_t>(nv));
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<char> used(size_t(nv), 0);
  for (int t = 0; t < nf; ++t) {
    const int32_t* f = triangle(m, t);
    for (int k = 0; k < 3; ++k) {
      if (f[k] < 0 || f[k] >= nv)
        return "triangle " + std::to_string(t) + " refers to vertex " + std::to_string(f[k]) + ", outside [0, " +
               std::to_string(nv) + ")";
    }
    if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2])
      return "triangle " + std::to_string(t) + " repeats a vertex (" + std::to_string(f[0]) + ", " +
             std::to_string(f[1]) + ", " + std::to_string(f[2]) + ")";
    // Degenerate when its area is negligible against its longest edge (angles near 0 or π make
    // cotangents blow up).
    const double *a = vertex(m, f[0]), *b = vertex(m, f[1]), *c = vertex(m, f[2]);
    double longest2 = 0;
    for (int k = 0; k < 3; ++k) {
      const double *p = vertex(m, f[k]), *q = vertex(m, f[(k + 1) % 3]);
      longest2 = std::max(longest2, (q[0] - p[0]) * (q[0] - p[0]) + (q[1] - p[1]) * (q[1] - p[1]));
    }
    if (std::abs(cross2(a, b, c)) <= 1e-12 * longest2)
      return "triangle " + std::to_string(t) + " (vertices " + std::to_string(f[0]) + ", " + std::to_string(f[1]) +
             ", " + std::to_string(f[2]) + ") is degenerate: its area is zero";
    for (int k = 0; k < 3; ++k) {
      used[f[k]] = 1;
      parent[find_root(parent, f[k])] = find_root(parent, f[(k + 1) % 3]);
    }
  }
  for (int v = 0; v < nv; ++v)
    if (!used[v]) return "vertex " + std::to_string(v) + " belongs to no triangle";
  if (handle_count < 1 || !handles) return "no handles: at least one handle vertex is needed";
  std::vector<int> owner(size_t(nv), -1);
  std::vector<char> component_has_handle(size_t(nv), 0);
  for (int j = 0; j < handle_count; ++j) {
    const int v = handles[j];
    if (v < 0 || v >= nv)
      return "handle " + std::to_string(j) + " is vertex " + std::to_string(v) + ", outside [0, " +
             std::to_string(nv) + ")";
    if (owner[v] >= 0)
      return "handles " + std::to_string(owner[v]) + " and " + std::to_string(j) + " are the same vertex " +
             std::to_string(v);
    owner[v] = j;
    component_has_handle[find_root(parent, v)] = 1;
  }
  for (int v = 0; v < nv; ++v)
    if (!component_has_handle[find_root(parent, v)])
      return "the part of the mesh containing vertex " + std::to_string(v) +
             " has no handle, so its weights are undetermined";
  return "";
}

// ---------------------------------------------------------------------------------------------
// Discrete operators
// ---------------------------------------------------------------------------------------------

void cotangent_laplacian(const MeshView2& m, SpMat& L) {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(12 * size_t(m.triangle_count));
  for (int t = 0; t < m.triangle_count; ++t) {
    const int32_t* f = triangle(m, t);
    for (int k = 0; k < 3; ++k) {
      // Edge (i, j) and the angle at o opposite it: cot = (a·b) / |a×b| with a = i − o, b = j − o.
      const int o = f[k], i = f[(k + 1) % 3], j = f[(k + 2) % 3];
      const double *po = vertex(m, o), *pi = vertex(m, i), *pj = vertex(m, j);
      const double ax = pi[0] - po[0], ay = pi[1] - po[1], bx = pj[0] - po[0], by = pj[1] - po[1];
      const double w = 0.5 * (ax * bx + ay * by) / std::abs(ax * by - ay * bx);
      entries.emplace_back(i, j, w);
      entries.emplace_back(j, i, w);
      entries.emplace_back(i, i, -w);
      entries.emplace_back(j, j, -w);
    }
  }
  L.resize(m.vertex_count, m.vertex_count);
  L.setFromTriplets(entries.begin(), entries.end());
}

void mass_matrix(const MeshView2& m, MassType type, SpMat& M) {
  Eigen::VectorXd area = Eigen::VectorXd::Zero(m.vertex_count);
  for (int t = 0; t < m.triangle_count; ++t) {
    const int32_t* f = triangle(m, t);
    const double A = 0.5 * std::abs(cross2(vertex(m, f[0]), vertex(m, f[1]), vertex(m, f[2])));
    if (type == MassType::kBarycentric) {
      for (int k = 0; k < 3; ++k) area[f[k]] += A / 3;
      continue;
    }
    // Squared length of the edge opposite vertex k, and the cotangent of the angle at k.
    double len2[3], cot[3];
    for (int k = 0; k < 3; ++k) {
      const double *o = vertex(m, f[k]), *p = vertex(m, f[(k + 1) % 3]), *q = vertex(m, f[(k + 2) % 3]);
      len2[k] = (q[0] - p[0]) * (q[0] - p[0]) + (q[1] - p[1]) * (q[1] - p[1]);
      cot[k] = ((p[0] - o[0]) * (q[0] - o[0]) + (p[1] - o[1]) * (q[1] - o[1])) / (2 * A);
    }
    const int obtuse = cot[0] < 0 ? 0 : cot[1] < 0 ? 1 : cot[2] < 0 ? 2 : -1;
    for (int k = 0; k < 3; ++k) {
      if (obtuse >= 0) {
        // The circumcenter lies outside: split the area ½ to the obtuse corner, ¼ to the others.
        area[f[k]] += k == obtuse ? A / 2 : A / 4;
      } else {
        // Voronoi cell of corner k: the two incident edges, each weighted by its opposite cotangent.
        const int a = (k + 1) % 3, b = (k + 2) % 3;
        area[f[k]] += (len2[a] * cot[a] + len2[b] * cot[b]) / 8;
      }
    }
  }
  M.resize(m.vertex_count, m.vertex_count);
  M.reserve(Eigen::VectorXi::Ones(m.vertex_count));
  for (int v = 0; v < m.vertex_count; ++v) M.insert(v, v) = area[v];
  M.makeCompressed();
}

// ---------------------------------------------------------------------------------------------
// Weights
// ---------------------------------------------------------------------------------------------

WeightsReport harmonic_weights(const MeshView2& mesh, const int32_t* handles, int handle_count, double* W) {
  WeightsReport report;
  report.error = validate_weights_input(mesh, handles, handle_count);
  if (!report.ok()) return report;
  SpMat L, Lff;
  Eigen::MatrixXd Lfh;
  cotangent_laplacian(mesh, L);
  const Split s = split_vertices(mesh.vertex_count, handles, handle_count);
  split_matrix(L, s, handle_count, Lff, Lfh);
  // Stationarity on the free vertices: L_ff x + L_fh δ_j = 0, i.e. (−L_ff) x = L_fh δ_j.
  Eigen::MatrixXd X(Lff.rows(), handle_count);
  if (Lff.rows() > 0) {
    Eigen::SimplicialLDLT<SpMat> ldlt(-Lff);
    if (ldlt.info() != Eigen::Success) {
      report.error = "internal: the Laplacian of the free vertices could not be factorized";
      return report;
    }
    X = ldlt.solve(Lfh);
  }
  for (int j = 0; j < handle_count; ++j) write_column(s, handle_count, j, X.col(j), W);
  return report;
}

WeightsReport bbw_weights(const MeshView2& mesh, const int32_t* handles, int handle_count, const BbwOptions& options,
                          double* W) {
  WeightsReport report;
  if (options.max_iterations < 1)
    report.error = "max iterations must be at least 1, got " + std::to_string(options.max_iterations);
  else if (!(options.bound_tolerance >= 0) || !std::isfinite(options.bound_tolerance))
    report.error = "bound tolerance must be finite and non-negative";
  else if (!(options.multiplier_tolerance >= 0) || !std::isfinite(options.multiplier_tolerance))
    report.error = "multiplier tolerance must be finite and non-negative";
  else
    report.error = validate_weights_input(mesh, handles, handle_count);
  if (!report.ok()) return report;

  // Q = L M⁻¹ L, the discrete bilaplacian energy ∫ (Δw)² with natural boundary conditions.
  SpMat L, M, Qff;
  Eigen::MatrixXd Qfh;
  cotangent_laplacian(mesh, L);
  mass_matrix(mesh, options.mass, M);
  const SpMat Q = L * (M.diagonal().cwiseInverse().asDiagonal() * L);
  const Split s = split_vertices(mesh.vertex_count, handles, handle_count);
  split_matrix(Q, s, handle_count, Qff, Qfh);
  const int n = int(Qff.rows());

  report.iterations.assign(size_t(handle_count), 0);
  Eigen::MatrixXd X(n, handle_count);
  if (n > 0) {
    SubsetSolver solver(Qff);
    // The unconstrained minimizers of all handles from one factorization: Q_ff x = −Q_fh δ_j.
    if (!solver.factorize(std::vector<char>(size_t(n), 1))) {
      report.error = "internal: the bilaplacian of the free vertices is not numerically positive definite";
      return report;
    }
    Eigen::VectorXd x(n);
    for (int j = 0; j < handle_count; ++j) {
      solver.solve(-Qfh.col(j), x);
      X.col(j) = x;
    }
    // Multiplier tolerance per vertex: tolerance · √M_ii / area^{3/2} (see BbwOptions).
    const double area = M.diagonal().sum();
    Eigen::VectorXd multiplier_tolerance(n);
    for (int k = 0; k < n; ++k)
      multiplier_tolerance[k] =
          options.multiplier_tolerance * std::sqrt(M.coeff(s.free[k], s.free[k])) / (area * std::sqrt(area));
    for (int j = 0; j < handle_count; ++j) {
      x = X.col(j);
      const BoxQpReport qp = solve_box_qp(Qff, Qfh.col(j), multiplier_tolerance, options, solver, x);
      if (!qp.error.empty()) {
        report.error = qp.error;
        return report;
      }
      report.iterations[j] = qp.solves;
      report.converged &= qp.converged;
      report.pinned += qp.pinned;
      X.col(j) = x;
    }
  }
  for (int j = 0; j < handle_count; ++j) write_column(s, handle_count, j, X.col(j), W);

  if (options.partition_of_unity) {
    for (int v = 0; v < mesh.vertex_count; ++v) {
      double* w = W + size_t(v) * handle_count;
      double sum = 0;
      for (int j = 0; j < handle_count; ++j) sum += w[j];
      // Every bounded weight can vanish at a vertex only on pathological meshes; share it equally then.
      for (int j = 0; j < handle_count; ++j) w[j] = sum > 0 ? w[j] / sum : 1.0 / handle_count;
    }
  }
  return report;
}

void triangle_weight_gradients(const MeshView2& m, const double* W, int handle_count, double* G) {
  for (int t = 0; t < m.triangle_count; ++t) {
    const int32_t* f = triangle(m, t);
    const double twice_area = cross2(vertex(m, f[0]), vertex(m, f[1]), vertex(m, f[2]));
    double* g = G + size_t(t) * handle_count * 2;
    std::fill(g, g + 2 * handle_count, 0.0);
    for (int k = 0; k < 3; ++k) {
      // ∇φ_k = rot90(e_k) / (2A_signed), e_k = the edge opposite corner k, rot90(x,y) = (−y,x).
      const double *p = vertex(m, f[(k + 1) % 3]), *q = vertex(m, f[(k + 2) % 3]);
      const double gx = -(q[1] - p[1]) / twice_area, gy = (q[0] - p[0]) / twice_area;
      const double* w = W + size_t(f[k]) * handle_count;
      for (int i = 0; i < handle_count; ++i) {
        g[2 * i] += w[i] * gx;
        g[2 * i + 1] += w[i] * gy;
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Point location and interpolation
// ---------------------------------------------------------------------------------------------

void build_triangle_grid(const MeshView2& m, TriangleGrid& grid) {
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (int v = 0; v < m.vertex_count; ++v)
    for (int a = 0; a < 2; ++a) lo[a] = std::min(lo[a], vertex(m, v)[a]), hi[a] = std::max(hi[a], vertex(m, v)[a]);
  const double w = hi[0] - lo[0], h = hi[1] - lo[1];
  // About one cell per triangle (square cells over the bounding box).
  grid.cell = std::sqrt(w * h / std::max(1, m.triangle_count));
  if (!(grid.cell > 0)) grid.cell = std::max(std::max(w, h), 1e-300);
  grid.x0 = lo[0];
  grid.y0 = lo[1];
  grid.nx = std::max(1, int(std::ceil(w / grid.cell)));
  grid.ny = std::max(1, int(std::ceil(h / grid.cell)));

  // Two passes over the triangles' bounding boxes: count per cell, then fill (CSR).
  const size_t cells = size_t(grid.nx) * grid.ny;
  grid.start.assign(cells + 1, 0);
  auto for_cells = [&](int t, auto&& visit) {
    const int32_t* f = triangle(m, t);
    double tlo[2] = {INFINITY, INFINITY}, thi[2] = {-INFINITY, -INFINITY};
    for (int k = 0; k < 3; ++k)
      for (int a = 0; a < 2; ++a)
        tlo[a] = std::min(tlo[a], vertex(m, f[k])[a]), thi[a] = std::max(thi[a], vertex(m, f[k])[a]);
    const int i0 = cell_index(tlo[0], grid.x0, grid.cell, grid.nx), i1 = cell_index(thi[0], grid.x0, grid.cell, grid.nx);
    const int j0 = cell_index(tlo[1], grid.y0, grid.cell, grid.ny), j1 = cell_index(thi[1], grid.y0, grid.cell, grid.ny);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) visit(size_t(j) * grid.nx + i);
  };
  for (int t = 0; t < m.triangle_count; ++t) for_cells(t, [&](size_t c) { ++grid.start[c + 1]; });
  for (size_t c = 0; c < cells; ++c) grid.start[c + 1] += grid.start[c];
  grid.items.resize(size_t(grid.start[cells]));
  std::vector<int32_t> fill(grid.start.begin(), grid.start.end() - 1);
  for (int t = 0; t < m.triangle_count; ++t) for_cells(t, [&](size_t c) { grid.items[fill[c]++] = t; });
}

int locate_point(const TriangleGrid& grid, const MeshView2& m, double x, double y, double* bary) {
  const int ci = cell_index(x, grid.x0, grid.cell, grid.nx), cj = cell_index(y, grid.y0, grid.cell, grid.ny);
  // Inside: a triangle of the point's cell contains it (up to rounding, which is clamped away).
  const size_t c = size_t(cj) * grid.nx + ci;
  for (int32_t e = grid.start[c]; e < grid.start[c + 1]; ++e) {
    const int t = grid.items[e];
    barycentric(m, t, x, y, bary);
    if (bary[0] >= -1e-12 && bary[1] >= -1e-12 && bary[2] >= -1e-12) {
      for (int k = 0; k < 3; ++k) bary[k] = std::max(bary[k], 0.0);
      const double sum = bary[0] + bary[1] + bary[2];
      for (int k = 0; k < 3; ++k) bary[k] /= sum;
      return t;
    }
  }
  // Outside: the nearest triangle, searching rings of cells outwards (ring r: the cells at
  // Chebyshev distance r from the point's cell, clamped into the grid) until no unvisited cell
  // can be nearer than the best triangle so far.
  int best = -1;
  double best_d2 = INFINITY, b[3];
  for (int r = 0;; ++r) {
    const double reach = ring_distance(grid, x, y, ci, cj, r);
    if (reach == INFINITY || (best >= 0 && best_d2 <= reach * reach)) break;
    for (int j = std::max(0, cj - r); j <= std::min(grid.ny - 1, cj + r); ++j) {
      const bool edge_row = j == cj - r || j == cj + r;
      for (int i = std::max(0, ci - r); i <= std::min(grid.nx - 1, ci + r); ++i) {
        if (!edge_row && i != ci - r && i != ci + r) continue;  // inside the ring: seen before
        const size_t cc = size_t(j) * grid.nx + i;
        for (int32_t e = grid.start[cc]; e < grid.start[cc + 1]; ++e) {
          const int t = grid.items[e];
          const double d2 = nearest_on_triangle(m, t, x, y, b);
          if (d2 < best_d2) {
            best_d2 = d2;
            best = t;
            std::copy(b, b + 3, bary);
          }
        }
      }
    }
  }
  return best;
}

void locate_and_interpolate(const TriangleGrid& grid, const MeshView2& m, const double* W, int handle_count,
                            const double* points, int point_count, double* out) {
  double b[3];
  for (int p = 0; p < point_count; ++p) {
    const int t = locate_point(grid, m, points[2 * p], points[2 * p + 1], b);
    const int32_t* f = triangle(m, t);
    const double *w0 = W + size_t(f[0]) * handle_count, *w1 = W + size_t(f[1]) * handle_count,
                 *w2 = W + size_t(f[2]) * handle_count;
    double* o = out + size_t(p) * handle_count;
    for (int i = 0; i < handle_count; ++i) o[i] = b[0] * w0[i] + b[1] * w1[i] + b[2] * w2[i];
  }
}

void locate_gradients(const TriangleGrid& grid, const MeshView2& m, const double* G, int handle_count,
                      const double* points, int point_count, double* out) {
  double b[3];
  const size_t stride = 2 * size_t(handle_count);
  for (int p = 0; p < point_count; ++p) {
    const int t = locate_point(grid, m, points[2 * p], points[2 * p + 1], b);
    std::copy(G + size_t(t) * stride, G + size_t(t + 1) * stride, out + size_t(p) * stride);
  }
}

}  // namespace splinekit::skin
