#include "weights.h"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "skin/box_qp.h"
#include "skin/subset_solver.h"

namespace splinekit::skin {

using SpMat = Eigen::SparseMatrix<double>;

namespace {

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

}  // namespace

// ---------------------------------------------------------------------------------------------
// Validation
// ---------------------------------------------------------------------------------------------

std::string validate_weights_input(const MeshView2& m, const int32_t* handles, int handle_count) {
  const int nv = m.vertex_count, nf = m.triangle_count;
  if (nv < 3 || !m.vertices) return "the mesh needs at least 3 vertices, got " + std::to_string(nv);
  if (nf < 1 || !m.triangles) return "the mesh has no triangle";
  for (int v = 0; v < nv; ++v)
    if (!std::isfinite(m.vertex(v)[0]) || !std::isfinite(m.vertex(v)[1]))
      return "vertex " + std::to_string(v) + " has a non-finite coordinate";
  std::vector<int> parent(static_cast<size_t>(nv));
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<char> used(size_t(nv), 0);
  for (int t = 0; t < nf; ++t) {
    const int32_t* f = m.triangle(t);
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
    double longest2 = 0;
    for (int k = 0; k < 3; ++k)
      longest2 = std::max(longest2, (m.position(f[(k + 1) % 3]) - m.position(f[k])).squaredNorm());
    if (std::abs(orient(m.position(f[0]), m.position(f[1]), m.position(f[2]))) <= 1e-12 * longest2)
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
      return "handle " + std::to_string(j) + " is vertex " + std::to_string(v) + ", outside [0, " + std::to_string(nv) +
             ")";
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

namespace {

std::string check_bbw_options(const BbwOptions& options) {
  if (options.max_iterations < 1)
    return "max iterations must be at least 1, got " + std::to_string(options.max_iterations);
  if (!(options.bound_tolerance >= 0) || !std::isfinite(options.bound_tolerance))
    return "bound tolerance must be finite and non-negative";
  if (!(options.multiplier_tolerance >= 0) || !std::isfinite(options.multiplier_tolerance))
    return "multiplier tolerance must be finite and non-negative";
  return "";
}

}  // namespace

WeightsReport bbw_weights(const MeshView2& mesh, const int32_t* handles, int handle_count, const BbwOptions& options,
                          double* W) {
  WeightsReport report;
  report.error = check_bbw_options(options);
  if (report.ok()) report.error = validate_weights_input(mesh, handles, handle_count);
  if (!report.ok()) return report;
  SpMat L, M;
  cotangent_laplacian(mesh, L);
  mass_matrix(mesh, options.mass, M);
  return bbw_weights_from_operators(L, M, handles, handle_count, options, W);
}

WeightsReport bbw_weights_from_operators(const SpMat& L, const SpMat& M, const int32_t* handles, int handle_count,
                                         const BbwOptions& options, double* W) {
  WeightsReport report;
  report.error = check_bbw_options(options);
  if (!report.ok()) return report;
  // Q = L M⁻¹ L, the discrete bilaplacian energy ∫ (Δw)² with natural boundary conditions.
  SpMat Qff;
  Eigen::MatrixXd Qfh;
  const SpMat Q = L * (M.diagonal().cwiseInverse().asDiagonal() * L);
  const int vertex_count = int(L.rows());
  const Split s = split_vertices(vertex_count, handles, handle_count);
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
    BoxQpOptions qp_options;
    qp_options.max_iterations = options.max_iterations;
    qp_options.bound_tolerance = options.bound_tolerance;
    for (int j = 0; j < handle_count; ++j) {
      x = X.col(j);
      const BoxQpReport qp = solve_box_qp(Qff, Qfh.col(j), multiplier_tolerance, qp_options, solver, x);
      if (!qp.error.empty()) {
        report.error = qp.error;
        return report;
      }
      report.iterations[j] = qp.solves;
      report.converged &= qp.converged;
      report.pinned += qp.pinned;
      X.col(j) = x;
      if (options.on_handle_solved) options.on_handle_solved(j + 1, handle_count);
    }
  }
  for (int j = 0; j < handle_count; ++j) write_column(s, handle_count, j, X.col(j), W);

  if (options.partition_of_unity) {
    for (int v = 0; v < vertex_count; ++v) {
      double* w = W + size_t(v) * handle_count;
      double sum = 0;
      for (int j = 0; j < handle_count; ++j) sum += w[j];
      // Every bounded weight can vanish at a vertex only on pathological meshes; share it equally then.
      for (int j = 0; j < handle_count; ++j) w[j] = sum > 0 ? w[j] / sum : 1.0 / handle_count;
    }
  }
  return report;
}

}  // namespace splinekit::skin
