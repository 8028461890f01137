#include "subdivision.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

namespace splinekit::skin3d {

namespace {

using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// Sharpness of a child half-edge: one level less, never below 0; +∞ stays +∞.
double decay(double s) { return std::isinf(s) ? s : std::max(0.0, s - 1.0); }

// Builds a row-major sparse matrix row by row (rows in order): a row's terms are summed per column
// as they come (slot[c] = where column c sits if it is already in the current row), sorted by
// column when the row ends. Cheaper than triplets on the finest level's millions of entries; the
// arrays only grow in the rare grow() (capacity from the caller's estimate), so add() stays small
// enough to inline.
struct Rows {
  std::vector<int> outer{0}, slot;
  std::unique_ptr<int[]> inner;
  std::unique_ptr<double[]> values;
  int size = 0, row_start = 0, capacity = 0;
  Rows(int cols, size_t estimate) : slot(size_t(cols), -1) { reserve(int(std::max<size_t>(estimate, 16))); }
  void reserve(int n) {
    std::unique_ptr<int[]> i(new int[size_t(n)]);
    std::unique_ptr<double[]> v(new double[size_t(n)]);
    std::copy(inner.get(), inner.get() + size, i.get());
    std::copy(values.get(), values.get() + size, v.get());
    inner.swap(i), values.swap(v), capacity = n;
  }
#if defined(__GNUC__)
  __attribute__((noinline))
#endif
  void
  grow() {
    reserve(2 * capacity);
  }
  void add(int col, double w) {
    if (w == 0.0) return;
    const int at = slot[col];
    if (at >= row_start) {  // earlier rows' positions are all below the current row's start
      values[at] += w;
      return;
    }
    if (size == capacity) grow();
    slot[col] = size, inner[size] = col, values[size] = w;
    ++size;
  }
  // w · (face point of f) = w/n · Σ face vertices.
  void add_face(const PolyMesh& m, int f, double w) {
    const int n = m.face_size(f);
    for (int c = m.face_start[f]; c < m.face_start[f + 1]; ++c) add(m.face_vertices[c], w / n);
  }
  void end_row() {
    // Insertion sort by column (rows hold a handful of distinct columns).
    for (int i = row_start + 1; i < size; ++i)
      for (int j = i; j > row_start && inner[j - 1] > inner[j]; --j)
        std::swap(inner[j - 1], inner[j]), std::swap(values[j - 1], values[j]);
    outer.push_back(size);
    row_start = size;
  }
  void to_matrix(int cols, RowSparse& S) const {
    S.resize(int(outer.size()) - 1, cols);
    S.resizeNonZeros(Eigen::Index(size));
    std::copy(outer.begin(), outer.end(), S.outerIndexPtr());
    std::copy(inner.get(), inner.get() + size, S.innerIndexPtr());
    std::copy(values.get(), values.get() + size, S.valuePtr());
  }
};

// How a vertex is refined (and limited): by its sharp edges (s > 0; boundary edges are +∞).
struct VertexRule {
  bool corner = false;  // three or more sharp edges, or a boundary vertex of a single face
  int sharp = 0;        // number of sharp edges
  int ends[2] = {-1, -1};
  double alpha = 0;  // weight of the crease/corner rule against the smooth one
};

VertexRule classify(const PolyMesh& p, int v) {
  VertexRule r;
  int boundary = 0;
  double sharpness = 0;
  for (int q = p.vertex_edge_start[v]; q < p.vertex_edge_start[v + 1]; ++q) {
    const int e = p.vertex_edges[q];
    boundary += p.boundary_edge(e);
    if (p.edge_sharpness[e] > 0) {
      if (r.sharp < 2) r.ends[r.sharp] = p.other_end(e, v);
      ++r.sharp;
      sharpness += p.edge_sharpness[e];
    }
  }
  const int faces = p.vertex_face_start[v + 1] - p.vertex_face_start[v];
  r.corner = r.sharp >= 3 || (boundary > 0 && faces == 1);
  // 1 on boundaries: s̄ = +∞.
  r.alpha = r.corner && boundary > 0 ? 1.0 : r.sharp >= 2 ? std::min(1.0, sharpness / r.sharp) : 0.0;
  return r;
}

// Weight of a corner tag's rule (the vertex itself) against the rule of its edges: min(1, s_v).
double vertex_corner(const PolyMesh& p, int v) {
  return p.vertex_sharpness.empty() ? 0.0 : std::min(1.0, p.vertex_sharpness[v]);
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// One level
// ---------------------------------------------------------------------------------------------

void refine_once(const PolyMesh& p, RowSparse& S, PolyMesh& child, bool with_topology) {
  const int nv = p.vertex_count, ne = p.edge_count(), nf = p.face_count();
  const int edge0 = nv, face0 = nv + ne;
  // Rows in child order: vertex points, edge points, face points.
  Rows rows(nv, size_t(nv) * 10 + size_t(ne) * 6 + p.face_vertices.size());
  rows.outer.reserve(size_t(nv + ne + nf) + 1);

  // Vertex points.
  for (int v = 0; v < nv; ++v) {
    const int e_begin = p.vertex_edge_start[v], e_end = p.vertex_edge_start[v + 1];
    const int f_begin = p.vertex_face_start[v], f_end = p.vertex_face_start[v + 1];
    const int valence = e_end - e_begin;
    if (valence == 0) {  // a vertex no face uses: carried along unchanged
      rows.add(v, 1.0);
      rows.end_row();
      continue;
    }
    // A corner tag: a·v + u·(the rule of the vertex's edges), a = min(1, s_v), u = 1 − a.
    const double a = vertex_corner(p, v), u = 1 - a;
    if (a > 0) rows.add(v, a);
    if (u > 0) {
      const VertexRule rule = classify(p, v);
      const bool corner = rule.corner;
      const double alpha = u * rule.alpha;
      const int* ends = rule.ends;
      if (corner) {
        rows.add(v, alpha);
      } else if (rule.sharp == 2) {
        rows.add(v, alpha * 0.75);
        rows.add(ends[0], alpha * 0.125);
        rows.add(ends[1], alpha * 0.125);
      }
      if (rule.alpha < 1) {
        const double n = valence, w = u * (1 - rule.alpha);
        rows.add(v, w * (n - 2) / n);
        for (int q = e_begin; q < e_end; ++q) rows.add(p.other_end(p.vertex_edges[q], v), w / (n * n));
        for (int q = f_begin; q < f_end; ++q) rows.add_face(p, p.vertex_faces[q], w / (n * n));
      }
    }
    rows.end_row();
  }
  // Edge points.
  for (int e = 0; e < ne; ++e) {
    const int a = p.edge_vertices[2 * e], b = p.edge_vertices[2 * e + 1];
    const double s = p.boundary_edge(e) ? 1.0 : std::min(p.edge_sharpness[e], 1.0);  // weight of the sharp rule
    rows.add(a, s * 0.5 + (1 - s) * 0.25);
    rows.add(b, s * 0.5 + (1 - s) * 0.25);
    if (s < 1) {
      rows.add_face(p, p.edge_faces[2 * e], 0.25 * (1 - s));
      rows.add_face(p, p.edge_faces[2 * e + 1], 0.25 * (1 - s));
    }
    rows.end_row();
  }

  // Face points.
  for (int f = 0; f < nf; ++f) rows.add_face(p, f, 1.0), rows.end_row();

  rows.to_matrix(nv, S);

  // Child faces: corner j of face f → (vertex j, edge point j→j+1, face point, edge point j−1→j).
  child = PolyMesh{};
  child.vertex_count = nv + ne + nf;
  child.face_start.resize(p.face_vertices.size() + 1);
  child.face_vertices.resize(4 * p.face_vertices.size());
  for (int f = 0, q = 0; f < nf; ++f) {
    const int base = p.face_start[f], n = p.face_size(f);
    for (int j = 0; j < n; ++j, ++q) {
      int* quad = &child.face_vertices[4 * size_t(q)];
      quad[0] = p.face_vertices[base + j];
      quad[1] = edge0 + p.corner_edge[base + j];
      quad[2] = face0 + f;
      quad[3] = edge0 + p.corner_edge[base + (j + n - 1) % n];
      child.face_start[q] = 4 * q;
    }
  }
  child.face_start.back() = int(child.face_vertices.size());
  if (!with_topology) return;
  build_topology(child);  // cannot fail: the child of a manifold mesh is manifold
  for (int e = 0; e < child.edge_count(); ++e) {
    if (child.boundary_edge(e)) continue;
    // Halves of a parent edge join a vertex point (< nv) to that edge's point.
    const int a = child.edge_vertices[2 * e], b = child.edge_vertices[2 * e + 1];
    if (a < nv && b >= edge0 && b < face0) child.edge_sharpness[e] = decay(p.edge_sharpness[b - edge0]);
  }
  // Corner tags decay like creases, on the vertex points (child v < #V descends from v).
  for (int v = 0; v < nv && v < int(p.vertex_sharpness.size()); ++v)
    child.vertex_sharpness[v] = decay(p.vertex_sharpness[v]);
}

// ---------------------------------------------------------------------------------------------
// Limit positions
// ---------------------------------------------------------------------------------------------

void limit_stencils(const PolyMesh& p, RowSparse& L) {
  Rows rows(p.vertex_count, size_t(p.vertex_count) * 10);
  for (int v = 0; v < p.vertex_count; ++v) {
    const int e_begin = p.vertex_edge_start[v], e_end = p.vertex_edge_start[v + 1];
    const int n = e_end - e_begin;
    const VertexRule rule = classify(p, v);
    // A corner tag: a·v + u·(the mask of the vertex's edges), as in refine_once.
    const double a = n == 0 ? 0.0 : vertex_corner(p, v), u = 1 - a;
    if (a > 0) rows.add(v, a);
    if (n == 0 || (rule.corner && u > 0)) rows.add(v, n == 0 ? 1.0 : u * rule.alpha);
    if (n > 0 && u > 0 && !rule.corner && rule.sharp == 2) {
      rows.add(v, u * rule.alpha * 4 / 6);
      rows.add(rule.ends[0], u * rule.alpha / 6);
      rows.add(rule.ends[1], u * rule.alpha / 6);
    }
    if (n > 0 && u > 0 && rule.alpha < 1) {
      const double w = u * (1 - rule.alpha) / (n * (n + 5.0));
      rows.add(v, w * n * n);
      for (int q = e_begin; q < e_end; ++q) rows.add(p.other_end(p.vertex_edges[q], v), 4 * w);
      for (int q = p.vertex_face_start[v]; q < p.vertex_face_start[v + 1]; ++q) {
        const int f = p.vertex_faces[q], base = p.face_start[f];
        int k = 0;
        while (p.face_vertices[base + k] != v) ++k;
        rows.add(p.face_vertices[base + (k + 2) % 4], w);  // the diagonal of a quad
      }
    }
    rows.end_row();
  }
  rows.to_matrix(p.vertex_count, L);
}

// ---------------------------------------------------------------------------------------------
// The chain
// ---------------------------------------------------------------------------------------------

void Subdivision::build(const PolyMesh& cage, int levels, bool final_topology) {
  cage_vertices_ = cage.vertex_count;
  cage_face_start_ = cage.face_start;
  steps_.assign(size_t(levels), RowSparse());
  scratch_.clear();
  PolyMesh current = cage, next;
  for (int j = 0; j < levels; ++j) {
    refine_once(current, steps_[j], next, j + 1 < levels || final_topology);
    current = std::move(next);
    next = PolyMesh{};
  }
  refined_ = std::move(current);
}

void Subdivision::apply(const double* cage, int cols, double* refined) {
  if (scratch_.size() + 1 != steps_.size() || (!scratch_.empty() && scratch_[0].rows() != cols)) {
    scratch_.clear();
    for (size_t j = 0; j + 1 < steps_.size(); ++j) scratch_.emplace_back(cols, steps_[j].rows());
  }
  const double* in = cage;
  for (size_t j = 0; j < steps_.size(); ++j) {
    const bool last = j + 1 == steps_.size();
    double* out = last ? refined : scratch_[j].data();
    Eigen::Map<const RowMatrix> X(in, steps_[j].cols(), cols);
    Eigen::Map<RowMatrix> Y(out, steps_[j].rows(), cols);
    Y.noalias() = steps_[j] * X;
    in = out;
  }
}

namespace {

// y += Sᵀ x for row-major x (S.rows() by cols) and y (S.cols() by cols): each stored entry of S adds
// one contiguous row of x to one of y.
void add_transpose_times(const RowSparse& S, const double* x, int cols, double* y) {
  const int* outer = S.outerIndexPtr();
  const int* inner = S.innerIndexPtr();
  const double* value = S.valuePtr();
  for (Eigen::Index r = 0; r < S.rows(); ++r) {
    const double* xr = x + size_t(r) * size_t(cols);
    for (int k = outer[r]; k < outer[r + 1]; ++k) {
      double* yc = y + size_t(inner[k]) * size_t(cols);
      const double s = value[k];
      for (int c = 0; c < cols; ++c) yc[c] += s * xr[c];
    }
  }
}

}  // namespace

Eigen::MatrixXd Subdivision::apply_transpose(int cols, const std::function<void(int, double*)>& row) const {
  const RowSparse& last = steps_.back();
  // Row-major in between: each stored entry of S_j then adds one contiguous row.
  RowMatrix x = RowMatrix::Zero(last.cols(), cols);
  {
    // Rows of G in blocks, so that the callback's writes and S_kᵀ's reads share a small buffer.
    constexpr int kBlock = 256;
    std::vector<double> g(size_t(kBlock) * size_t(cols), 0.0);
    const int* outer = last.outerIndexPtr();
    const int* inner = last.innerIndexPtr();
    const double* value = last.valuePtr();
    double* X = x.data();
    for (int r0 = 0; r0 < last.rows(); r0 += kBlock) {
      const int r1 = std::min(int(last.rows()), r0 + kBlock);
      for (int r = r0; r < r1; ++r) row(r, &g[size_t(r - r0) * size_t(cols)]);
      for (int r = r0; r < r1; ++r) {
        const double* gr = &g[size_t(r - r0) * size_t(cols)];
        for (int k = outer[r]; k < outer[r + 1]; ++k) {
          double* xc = X + size_t(inner[k]) * size_t(cols);
          const double s = value[k];
          for (int c = 0; c < cols; ++c) xc[c] += s * gr[c];
        }
      }
    }
  }
  for (size_t j = steps_.size() - 1; j-- > 0;) {
    RowMatrix y = RowMatrix::Zero(steps_[j].cols(), cols);
    add_transpose_times(steps_[j], x.data(), cols, y.data());
    x.swap(y);
  }
  return x;
}

namespace {

// X · Y for row-major sparse matrices, row by row (Gustavson): row i gathers x_ik · (row k of Y),
// written sorted straight into row-major arrays (Eigen's product goes through two storage-order
// conversions: ~25% slower here).
RowSparse multiply(const RowSparse& X, const RowSparse& Y) {
  const int rows = int(X.rows()), cols = int(Y.cols());
  std::vector<double> acc(size_t(cols), 0.0), values;
  std::vector<int> mark(size_t(cols), -1), touched, outer{0}, inner;
  // An upper bound of the products (one pass over X) sizes the output once.
  size_t bound = 0;
  for (int k = 0; k < X.outerSize(); ++k)
    for (RowSparse::InnerIterator xk(X, k); xk; ++xk)
      bound += size_t(Y.outerIndexPtr()[xk.col() + 1] - Y.outerIndexPtr()[xk.col()]);
  outer.reserve(size_t(rows) + 1), inner.reserve(bound), values.reserve(bound);
  for (int i = 0; i < rows; ++i) {
    touched.clear();
    for (RowSparse::InnerIterator xk(X, i); xk; ++xk)
      for (RowSparse::InnerIterator yj(Y, xk.col()); yj; ++yj) {
        const int j = int(yj.col());
        if (mark[j] != i) mark[j] = i, acc[j] = 0, touched.push_back(j);
        acc[j] += xk.value() * yj.value();
      }
    std::sort(touched.begin(), touched.end());
    for (int j : touched) inner.push_back(j), values.push_back(acc[j]);
    outer.push_back(int(inner.size()));
  }
  return Eigen::Map<const RowSparse>(rows, cols, int(inner.size()), outer.data(), inner.data(), values.data());
}

// Sᵀ A S for a symmetric sparse A: (A S) first, then Sᵀ (A S) — fewer products than one triple
// loop, since S has only a few entries per row.
RowSparse congruence(const RowSparse& S, const RowSparse& A) {
  const RowSparse St = S.transpose();
  return multiply(St, multiply(A, S));
}

}  // namespace

Eigen::SparseMatrix<double> Subdivision::gram(const Eigen::VectorXd& D) const {
  RowSparse A(D.size(), D.size());
  A.reserve(Eigen::VectorXi::Ones(D.size()));
  for (Eigen::Index r = 0; r < D.size(); ++r) A.insert(r, r) = D[r];
  for (size_t j = steps_.size(); j-- > 0;) A = congruence(steps_[j], A);
  // Symmetric: its row-major arrays are also its column-major ones (no conversion).
  return Eigen::Map<const Eigen::SparseMatrix<double>>(A.rows(), A.cols(), A.nonZeros(), A.outerIndexPtr(),
                                                       A.innerIndexPtr(), A.valuePtr());
}

Eigen::SparseMatrix<double> Subdivision::gram_lower(const Eigen::VectorXd& D) const {
  Eigen::MatrixXd unused;
  return normal_equations(D, 0, nullptr, unused);
}

Eigen::SparseMatrix<double> Subdivision::normal_equations(const Eigen::VectorXd& D, int width,
                                                          const std::function<void(int, double*)>& row,
                                                          Eigen::MatrixXd& MtG) const {
  const int K = levels(), n0 = cage_vertices_, R = refined_vertex_count();
  const int nf = int(cage_face_start_.size()) - 1;
  // ---- Groups: the level-K vertices each cage face owns ----------------------------------------
  // Level-1 quads of cage face f are its corners [start_f, start_{f+1}); every later level splits
  // quad q into 4q … 4q+3, so f's level-K quads are 4^(K−1) times that range.
  const size_t per_corner = size_t(1) << (2 * (K - 1));
  const std::vector<int>& quads = refined_.face_vertices;
  std::vector<int> group_start{0}, group_rows;
  group_start.reserve(size_t(nf) + 1), group_rows.reserve(size_t(R));
  std::vector<char> owned(size_t(R), 0);
  for (int f = 0; f < nf; ++f) {
    for (size_t q = per_corner * size_t(cage_face_start_[f]); q < per_corner * size_t(cage_face_start_[f + 1]); ++q)
      for (int k = 0; k < 4; ++k) {
        const int r = quads[4 * q + size_t(k)];
        if (!owned[r]) owned[r] = 1, group_rows.push_back(r);
      }
    std::sort(group_rows.begin() + group_start.back(), group_rows.end());  // memory order
    group_start.push_back(int(group_rows.size()));
  }
  for (int r = 0; r < R; ++r)
    if (!owned[r]) group_rows.push_back(r), group_start.push_back(int(group_rows.size()));
  const int groups = int(group_start.size()) - 1;

  // ---- Per group: the vertices in between, then dense rows of M --------------------------------
  // level[j] lists the group's level-j vertices (level K: its rows; level j−1: the columns of
  // S_j on level[j], in order of appearance). slot[j][v] = {group, position of v in level[j]}.
  // S_j restricted to the group is copied once, with local column numbers, into rows_at[j]
  // (offsets), local_col[j] and weight[j]: the numeric pass then reads only small arrays.
  struct Slot {
    int group = -1, at = 0;
  };
  const size_t KK = size_t(K) + 1;
  std::vector<std::vector<int>> level(KK), rows_at(KK), local_col(KK);
  std::vector<std::vector<double>> weight(KK), dense(KK);  // dense[j]: #level[j] by m, row-major
  std::vector<std::vector<Slot>> slot(KK);
  for (int j = 0; j < K; ++j) slot[j].assign(size_t(j == 0 ? n0 : int(steps_[size_t(j) - 1].rows())), Slot{});
  // Each group's cage vertices (sorted) and the lower triangle of its block, row by row.
  std::vector<int> cols_start{0}, cols, rank;
  std::vector<std::pair<int, int>> sorted;
  std::vector<size_t> block_start{0};
  std::vector<double> blocks, scaled;
  cols.reserve(size_t(groups) * 20), blocks.reserve(size_t(groups) * 210);
  Eigen::MatrixXd C;
  // Ŵ: S_kᵀ G per group (its rows of S_k are at hand), summed into the level-(k−1) rows X.
  using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  const int below_finest = K == 1 ? n0 : int(steps_[size_t(K) - 2].rows());
  RowMatrix X = RowMatrix::Zero(width > 0 ? below_finest : 0, width);
  std::vector<double> g_rows, y;
  for (int g = 0; g < groups; ++g) {
    level[K].assign(group_rows.begin() + group_start[g], group_rows.begin() + group_start[g + 1]);
    for (int j = K; j >= 1; --j) {
      const RowSparse& S = steps_[size_t(j) - 1];
      const int* outer = S.outerIndexPtr();
      const int* inner = S.innerIndexPtr();
      const double* value = S.valuePtr();
      std::vector<int>& below = level[size_t(j) - 1];
      std::vector<Slot>& where = slot[size_t(j) - 1];
      below.clear(), rows_at[j].assign(1, 0), local_col[j].clear(), weight[j].clear();
      for (int v : level[j]) {
        for (int k = outer[v]; k < outer[v + 1]; ++k) {
          Slot& w = where[inner[k]];
          if (w.group != g) w.group = g, w.at = int(below.size()), below.push_back(inner[k]);
          local_col[j].push_back(w.at), weight[j].push_back(value[k]);
        }
        rows_at[j].push_back(int(local_col[j].size()));
      }
      // Sorted, so that the next level reads its rows of S_(j−1) (and level 0 its block's lower
      // triangle, the global one's) in memory order.
      const int n = int(below.size());
      sorted.resize(size_t(n)), rank.resize(size_t(n));
      for (int a = 0; a < n; ++a) sorted[a] = {below[a], a};
      std::sort(sorted.begin(), sorted.end());
      for (int a = 0; a < n; ++a) rank[sorted[a].second] = a, below[a] = sorted[a].first;
      for (int& c : local_col[j]) c = rank[c];
    }
    if (width > 0) {
      const size_t n = level[K].size(), c = size_t(width);
      g_rows.resize(n * c);
      for (size_t i = 0; i < n; ++i) row(level[K][i], &g_rows[i * c]);
      y.assign(level[K - 1].size() * c, 0.0);
      const int* at = rows_at[K].data();
      const int* lc = local_col[K].data();
      const double* wt = weight[K].data();
      for (size_t i = 0; i < n; ++i) {
        const double* gi = &g_rows[i * c];
        for (int k = at[i]; k < at[i + 1]; ++k) {
          double* yk = &y[size_t(lc[k]) * c];
          const double w = wt[k];
          for (size_t e = 0; e < c; ++e) yk[e] += w * gi[e];
        }
      }
      for (size_t a = 0; a < level[K - 1].size(); ++a) {
        double* x = X.data() + size_t(level[K - 1][a]) * c;
        for (size_t e = 0; e < c; ++e) x[e] += y[a * c + e];
      }
    }
    const int m = int(level[0].size());
    // dense[1] = S_1 restricted; dense[j] = S_j restricted · dense[j−1].
    for (int j = 1; j <= K; ++j) {
      const size_t n = level[j].size();
      std::vector<double>& out = dense[j];
      out.assign(n * size_t(m), 0.0);
      const int* at = rows_at[j].data();
      const int* lc = local_col[j].data();
      const double* wt = weight[j].data();
      for (size_t i = 0; i < n; ++i) {
        double* row = &out[i * size_t(m)];
        if (j == 1) {
          for (int k = at[i]; k < at[i + 1]; ++k) row[lc[k]] += wt[k];
        } else {
          const double* prev = dense[size_t(j) - 1].data();
          for (int k = at[i]; k < at[i + 1]; ++k) {
            const double w = wt[k];
            const double* in = prev + size_t(lc[k]) * size_t(m);
            for (int a = 0; a < m; ++a) row[a] += w * in[a];
          }
        }
      }
    }
    // Σ_r D_r b_r b_rᵀ over the group's rows b_r: Bᵀ (D B), then its lower triangle.
    const int n = int(level[K].size());
    const Eigen::Map<const RowMatrix> B(dense[K].data(), n, m);
    scaled.resize(size_t(n) * size_t(m));
    Eigen::Map<RowMatrix> DB(scaled.data(), n, m);
    for (int i = 0; i < n; ++i) DB.row(i) = D[level[K][i]] * B.row(i);
    C.resize(m, m);
    C.noalias() = B.transpose() * DB;
    for (int a = 0; a < m; ++a) {
      cols.push_back(level[0][a]);
      for (int e = 0; e <= a; ++e) blocks.push_back(C(a, e));
    }
    cols_start.push_back(int(cols.size()));
    block_start.push_back(blocks.size());
  }

  if (width > 0) {  // the coarser levels of Ŵ: S_(k−1)ᵀ … S_1ᵀ X
    for (int j = K - 1; j >= 1; --j) {
      RowMatrix Y = RowMatrix::Zero(steps_[size_t(j) - 1].cols(), width);
      add_transpose_times(steps_[size_t(j) - 1], X.data(), width, Y.data());
      X.swap(Y);
    }
    MtG = X;
  }

  // ---- Assembly of the lower triangle (column-major) -----------------------------------------
  // Column b holds every a ≥ b that shares a group with b.
  std::vector<int> vg_start(size_t(n0) + 1, 0), vg;  // cage vertex → the groups it is in
  for (int c : cols) ++vg_start[c + 1];
  for (int v = 0; v < n0; ++v) vg_start[v + 1] += vg_start[v];
  vg.resize(cols.size());
  {
    std::vector<int> fill(vg_start.begin(), vg_start.end() - 1);
    for (int g = 0; g < groups; ++g)
      for (int k = cols_start[g]; k < cols_start[g + 1]; ++k) vg[fill[cols[k]]++] = g;
  }
  std::vector<int> outer(size_t(n0) + 1, 0), inner, mark(size_t(n0), -1);
  inner.reserve(cols.size() * 8);
  for (int b = 0; b < n0; ++b) {
    const size_t first = inner.size();
    for (int q = vg_start[b]; q < vg_start[b + 1]; ++q) {
      const int g = vg[q];
      for (int k = cols_start[g]; k < cols_start[g + 1]; ++k) {
        const int a = cols[k];
        if (a >= b && mark[a] != b) mark[a] = b, inner.push_back(a);
      }
    }
    std::sort(inner.begin() + std::ptrdiff_t(first), inner.end());
    outer[b + 1] = int(inner.size());
  }
  std::vector<double> values(inner.size(), 0.0);
  for (int g = 0; g < groups; ++g) {
    const int* base = &cols[cols_start[g]];
    const int m = cols_start[g + 1] - cols_start[g];
    const double* c = &blocks[block_start[g]];
    // Block entry (a, e), a ≥ e (local), sits at a(a+1)/2 + e; column base[e] takes rows base[a ≥ e],
    // found by walking that column's sorted rows once.
    for (int e = 0; e < m; ++e) {
      int at = outer[base[e]];
      for (int a = e; a < m; ++a) {
        while (inner[at] != base[a]) ++at;
        values[at] += c[size_t(a) * size_t(a + 1) / 2 + size_t(e)];
      }
    }
  }
  return Eigen::Map<const Eigen::SparseMatrix<double>>(n0, n0, int(inner.size()), outer.data(), inner.data(),
                                                       values.data());
}

RowSparse Subdivision::compose() const {
  RowSparse M(cage_vertices_, cage_vertices_);
  M.setIdentity();
  for (const RowSparse& S : steps_) M = RowSparse(S * M);
  return M;
}

size_t Subdivision::memory_bytes() const {
  size_t bytes = 0;
  for (const RowSparse& S : steps_)
    bytes += size_t(S.nonZeros()) * (sizeof(double) + sizeof(int)) + size_t(S.outerSize() + 1) * sizeof(int);
  return bytes;
}

}  // namespace splinekit::skin3d
