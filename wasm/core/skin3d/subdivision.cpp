#include "subdivision.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace splinekit::skin3d {

namespace {

using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// Sharpness of a child half-edge: one level less, never below 0; +∞ stays +∞.
double decay(double s) { return std::isinf(s) ? s : std::max(0.0, s - 1.0); }

// Builds a row-major sparse matrix row by row (rows in order): each row's terms are summed per
// column when the row ends. Cheaper than triplets on the finest level's millions of entries.
struct Rows {
  std::vector<int> outer{0}, inner;
  std::vector<double> values;
  void add(int col, double w) {
    if (w != 0.0) inner.push_back(col), values.push_back(w);
  }
  // w · (face point of f) = w/n · Σ face vertices.
  void add_face(const PolyMesh& m, int f, double w) {
    const int n = m.face_size(f);
    for (int c = m.face_start[f]; c < m.face_start[f + 1]; ++c) add(m.face_vertices[c], w / n);
  }
  void end_row() {
    // Insertion sort by column (rows hold a few dozen terms), then merge equal columns.
    const int begin = outer.back(), end = int(inner.size());
    for (int i = begin + 1; i < end; ++i)
      for (int j = i; j > begin && inner[j - 1] > inner[j]; --j)
        std::swap(inner[j - 1], inner[j]), std::swap(values[j - 1], values[j]);
    int out = begin;
    for (int i = begin; i < end; ++i) {
      if (out > begin && inner[out - 1] == inner[i]) {
        values[out - 1] += values[i];
      } else {
        inner[out] = inner[i], values[out] = values[i];
        ++out;
      }
    }
    inner.resize(size_t(out)), values.resize(size_t(out));
    outer.push_back(out);
  }
  void to_matrix(int cols, RowSparse& S) const {
    S = Eigen::Map<const RowSparse>(int(outer.size()) - 1, cols, int(inner.size()), outer.data(), inner.data(),
                                    values.data());
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

}  // namespace

// ---------------------------------------------------------------------------------------------
// One level
// ---------------------------------------------------------------------------------------------

void refine_once(const PolyMesh& p, RowSparse& S, PolyMesh& child, bool with_topology) {
  const int nv = p.vertex_count, ne = p.edge_count(), nf = p.face_count();
  const int edge0 = nv, face0 = nv + ne;
  // Rows in child order: vertex points, edge points, face points.
  Rows rows;
  rows.outer.reserve(size_t(nv + ne + nf) + 1);
  rows.inner.reserve(size_t(nv) * 16 + size_t(ne) * 8 + p.face_vertices.size());
  rows.values.reserve(rows.inner.capacity());

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
    const VertexRule rule = classify(p, v);
    const bool corner = rule.corner;
    const double alpha = rule.alpha;
    const int* ends = rule.ends;
    if (corner) {
      rows.add(v, alpha);
    } else if (rule.sharp == 2) {
      rows.add(v, alpha * 0.75);
      rows.add(ends[0], alpha * 0.125);
      rows.add(ends[1], alpha * 0.125);
    }
    if (alpha < 1) {
      const double n = valence, w = 1 - alpha;
      rows.add(v, w * (n - 2) / n);
      for (int q = e_begin; q < e_end; ++q) rows.add(p.other_end(p.vertex_edges[q], v), w / (n * n));
      for (int q = f_begin; q < f_end; ++q) rows.add_face(p, p.vertex_faces[q], w / (n * n));
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
}

// ---------------------------------------------------------------------------------------------
// Limit positions
// ---------------------------------------------------------------------------------------------

void limit_stencils(const PolyMesh& p, RowSparse& L) {
  Rows rows;
  for (int v = 0; v < p.vertex_count; ++v) {
    const int e_begin = p.vertex_edge_start[v], e_end = p.vertex_edge_start[v + 1];
    const int n = e_end - e_begin;
    const VertexRule rule = classify(p, v);
    if (n == 0 || rule.corner) rows.add(v, n == 0 ? 1.0 : rule.alpha);
    if (n > 0 && !rule.corner && rule.sharp == 2) {
      rows.add(v, rule.alpha * 4 / 6);
      rows.add(rule.ends[0], rule.alpha / 6);
      rows.add(rule.ends[1], rule.alpha / 6);
    }
    if (n > 0 && rule.alpha < 1) {
      const double w = (1 - rule.alpha) / (n * (n + 5.0));
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

Eigen::MatrixXd Subdivision::apply_transpose(int cols, const std::function<void(int, double*)>& row) const {
  const RowSparse& last = steps_.back();
  RowMatrix x = RowMatrix::Zero(last.cols(), cols);
  std::vector<double> g(size_t(cols), 0.0);
  for (int r = 0; r < last.rows(); ++r) {
    row(r, g.data());
    for (RowSparse::InnerIterator it(last, r); it; ++it)
      x.row(it.col()) += it.value() * Eigen::Map<const Eigen::RowVectorXd>(g.data(), cols);
  }
  // Row-major in between: each stored entry of S_j then adds one contiguous row.
  for (size_t j = steps_.size() - 1; j-- > 0;) x = steps_[j].transpose() * x;
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
