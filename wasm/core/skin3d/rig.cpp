#include "rig.h"

#include <Eigen/Geometry>
#include <Eigen/OrderingMethods>
#include <algorithm>
#include <cmath>

#include "common/geometry.h"
#include "skin/shepard.h"
#include "skin/supernodal_cholesky.h"

namespace splinekit::skin3d {

namespace {

bool finite(const std::vector<double>& v) {
  for (double x : v)
    if (!std::isfinite(x)) return false;
  return true;
}

Vec3 vec3_at(const double* xyz, int k) { return {xyz[3 * size_t(k)], xyz[3 * size_t(k) + 1], xyz[3 * size_t(k) + 2]}; }

// Both triangles of the symmetric matrix whose lower triangle is L, rows and columns renumbered:
// entry (r, c) of L goes to (position[r], position[c]) and its mirror.
Eigen::SparseMatrix<double> permuted_full(const Eigen::SparseMatrix<double>& L, const std::vector<int>& position) {
  const int n = int(L.rows());
  std::vector<int> outer(size_t(n) + 1, 0);
  for (int c = 0; c < n; ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(L, c); it; ++it) {
      ++outer[position[c] + 1];
      if (it.row() != c) ++outer[position[it.row()] + 1];
    }
  for (int c = 0; c < n; ++c) outer[c + 1] += outer[c];
  Eigen::SparseMatrix<double> P(n, n);
  P.resizeNonZeros(outer[n]);
  std::copy(outer.begin(), outer.end(), P.outerIndexPtr());
  std::vector<int> fill(outer.begin(), outer.end() - 1);
  for (int c = 0; c < n; ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(L, c); it; ++it) {
      const int pc = position[c], pr = position[it.row()];
      P.innerIndexPtr()[fill[pc]] = pr, P.valuePtr()[fill[pc]++] = it.value();
      if (it.row() != c) P.innerIndexPtr()[fill[pr]] = pc, P.valuePtr()[fill[pr]++] = it.value();
    }
  return P;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Setup
// ---------------------------------------------------------------------------------------------

std::string SubdivisionRig::setup(const double* positions, int vertex_count, const int* face_sizes, int face_count,
                                  const int* face_indices, const Crease* creases, int crease_count, int levels,
                                  int handle_count, const Corner* corners, int corner_count) {
  ready_ = false;
  if (levels < 1 || levels > 4) return "levels must be in 1..4, got " + std::to_string(levels);
  if (handle_count < 1) return "a rig needs at least one handle";
  for (int v = 0; v < vertex_count; ++v)
    for (int a = 0; a < 3; ++a)
      if (!std::isfinite(positions[3 * size_t(v) + a]))
        return "vertex " + std::to_string(v + 1) + " has a non-finite coordinate";
  if (std::string e = make_poly_mesh(vertex_count, face_sizes, face_count, face_indices, mesh_); !e.empty()) return e;
  if (std::string e = apply_creases(creases, crease_count, mesh_); !e.empty()) return e;
  if (std::string e = apply_corners(corners, corner_count, mesh_); !e.empty()) return e;
  handles_ = handle_count;
  rest_cage_.assign(positions, positions + 3 * size_t(vertex_count));
  subdivision_.build(mesh_, levels);
  const int R = subdivision_.refined_vertex_count();
  rest_refined_.assign(3 * size_t(R), 0.0);
  subdivision_.apply(rest_cage_.data(), 3, rest_refined_.data());

  // Area per refined vertex: a quarter of each incident quad (vector area of the quad).
  const PolyMesh& fine = subdivision_.refined_mesh();
  areas_.assign(size_t(R), 0.0);
  triangles_.resize(6 * size_t(fine.face_count()));
  for (int f = 0; f < fine.face_count(); ++f) {
    const int* q = &fine.face_vertices[4 * size_t(f)];
    const Vec3 d0 = vec3_at(rest_refined_.data(), q[2]) - vec3_at(rest_refined_.data(), q[0]);
    const Vec3 d1 = vec3_at(rest_refined_.data(), q[3]) - vec3_at(rest_refined_.data(), q[1]);
    const double a = 0.5 * d0.cross(d1).norm();
    for (int k = 0; k < 4; ++k) areas_[q[k]] += a / 4;
    const int tri[6] = {q[0], q[1], q[2], q[0], q[2], q[3]};
    std::copy(tri, tri + 6, &triangles_[6 * size_t(f)]);
  }
  // A cage vertex no face uses is carried to the refined surface unchanged with no area; give it
  // the mean area so that the fit moves it by its own blend (as the 2D rig's lone points).
  double total = 0;
  for (double a : areas_) total += a;
  for (double& a : areas_)
    if (!(a > 0)) a = total > 0 ? total / R : 1.0;

  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
  for (int r = 0; r < R; ++r)
    lo = lo.cwiseMin(vec3_at(rest_refined_.data(), r)), hi = hi.cwiseMax(vec3_at(rest_refined_.data(), r));
  diagonal_ = (hi - lo).norm();
  if (!(diagonal_ > 0)) diagonal_ = 1;

  refined_weights_.assign(size_t(R) * handle_count, 0.0);
  cage_weights_.assign(size_t(vertex_count) * handle_count, 0.0);
  cage_.assign(3 * size_t(vertex_count), 0.0);
  planar_.assign(3 * size_t(vertex_count), 0.0);
  naive_.assign(3 * size_t(vertex_count), 0.0);
  refined_.assign(3 * size_t(R), 0.0);
  target_.assign(3 * size_t(R), 0.0);
  return "";
}

void SubdivisionRig::use_shepard(const double* handles, double power) {
  skin::shepard_weights_nd(handles, handles_, rest_refined_.data(), refined_vertex_count(), 3, power,
                           refined_weights_.data());
  skin::shepard_weights_nd(handles, handles_, rest_cage_.data(), cage_vertex_count(), 3, power, cage_weights_.data());
}

void SubdivisionRig::prolongate_cage_weights() {
  subdivision_.apply(cage_weights_.data(), handles_, refined_weights_.data());
}

void SubdivisionRig::restrict_refined_weights() {
  std::copy(refined_weights_.begin(), refined_weights_.begin() + cage_weights_.size(), cage_weights_.begin());
}

// ---------------------------------------------------------------------------------------------
// Precompute
// ---------------------------------------------------------------------------------------------

std::string SubdivisionRig::precompute() {
  ready_ = false;
  if (!finite(refined_weights_) || !finite(cage_weights_)) return "skinning weights contain a non-finite value";
  const int R = refined_vertex_count(), H = handles_;
  const Eigen::Map<const Eigen::VectorXd> D(areas_.data(), R);

  // Ŵ for every handle at once: G(r, 4i + c) = D_r w_ir [p_r; 1]_c, then Mᵀ G (G streamed row by
  // row, never stored), in the same pass over the cage faces as Â = Mᵀ D M (its lower triangle, all
  // the ordering and the factorization read).
  Eigen::MatrixXd B;
  Eigen::SparseMatrix<double> A = subdivision_.normal_equations(
      D, 4 * H,
      [&](int r, double* g) {
        const double* w = &refined_weights_[size_t(r) * H];
        const double* p = &rest_refined_[3 * size_t(r)];
        for (int i = 0; i < H; ++i) {
          const double dw = D[r] * w[i];
          g[4 * i] = dw * p[0], g[4 * i + 1] = dw * p[1], g[4 * i + 2] = dw * p[2], g[4 * i + 3] = dw;
        }
      },
      B);

  // M can be rank-deficient: on the cube (every vertex of valence 3) the checkerboard ±1 of the
  // cage vertices subdivides to 0. A small pull of each cage vertex toward its own blend,
  // ε Σ_v |X_v − Σ_i w_iv T_i [p_v; 1]|², picks the solution in that null space; it vanishes
  // whenever the cage itself is optimal (identity, a shared transform) and changes nothing else
  // measurably (ε = 1e-6 of the mean refined-vertex area).
  const double eps = 1e-6 * D.sum() / R;
  for (int v = 0; v < cage_vertex_count(); ++v) {
    A.coeffRef(v, v) += eps;
    const double* p = &rest_cage_[3 * size_t(v)];
    const double* w = &cage_weights_[size_t(v) * H];
    for (int i = 0; i < H; ++i) {
      B(v, 4 * i) += eps * w[i] * p[0], B(v, 4 * i + 1) += eps * w[i] * p[1];
      B(v, 4 * i + 2) += eps * w[i] * p[2], B(v, 4 * i + 3) += eps * w[i];
    }
  }
  // Sparse Cholesky: a fill-reducing order (AMD) of Â, then the supernodal factorization of the 2D
  // skin's weights (dense fronts), one solve per column of B.
  const int N = cage_vertex_count();
  Eigen::AMDOrdering<int> amd;
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> order;
  amd(A, order);                             // reads the symmetric pattern of the stored (lower) triangle
  const int* elim = order.indices().data();  // elim[k] = the cage vertex eliminated k-th
  std::vector<int> position(static_cast<size_t>(N));
  for (int k = 0; k < N; ++k) position[elim[k]] = k;
  Eigen::SparseMatrix<double> P = permuted_full(A, position);
  skin::SupernodalCholesky cholesky;
  if (!cholesky.factorize(P)) return "internal: Mᵀ D M could not be factorized";
  O_.resize(N, B.cols());
  std::vector<double> y(static_cast<size_t>(N));
  for (Eigen::Index c = 0; c < B.cols(); ++c) {
    for (int k = 0; k < N; ++k) y[k] = B(elim[k], c);
    cholesky.solve(y.data());
    for (int k = 0; k < N; ++k) O_(elim[k], c) = y[k];
  }
  if (!O_.allFinite()) return "internal: Mᵀ D M is singular for this cage";
  ready_ = true;
  return "";
}

// ---------------------------------------------------------------------------------------------
// Per frame
// ---------------------------------------------------------------------------------------------

const double* SubdivisionRig::update(const double* T) {
  const int N = cage_vertex_count();
  if (!ready_) {
    std::copy(rest_cage_.begin(), rest_cage_.end(), cage_.begin());
    return cage_.data();
  }
  double* x = planar_.data();
  double* y = x + N;
  double* z = y + N;
  std::fill(planar_.begin(), planar_.end(), 0.0);
  // X = O · [T_1ᵀ; …; T_Hᵀ]: column 4i + c of O meets row c of T_iᵀ = column c of [A_i | t_i].
  // In blocks of vertices, so that the three output planes stay in cache while O streams by once.
  constexpr int kBlock = 512;
  for (int v0 = 0; v0 < N; v0 += kBlock) {
    const int v1 = std::min(N, v0 + kBlock);
    for (int i = 0; i < handles_; ++i)
      for (int c = 0; c < 4; ++c) {
        const double* o = O_.col(4 * i + c).data();
        const double tx = T[12 * i + c], ty = T[12 * i + 4 + c], tz = T[12 * i + 8 + c];
        for (int v = v0; v < v1; ++v) {
          x[v] += o[v] * tx;
          y[v] += o[v] * ty;
          z[v] += o[v] * tz;
        }
      }
  }
  for (int v = 0; v < N; ++v) cage_[3 * v] = x[v], cage_[3 * v + 1] = y[v], cage_[3 * v + 2] = z[v];
  return cage_.data();
}

void SubdivisionRig::blend(const std::vector<double>& rest, const std::vector<double>& weights, const double* T,
                           std::vector<double>& out) const {
  const int H = handles_, n = int(rest.size() / 3);
  for (int v = 0; v < n; ++v) {
    const double* p = &rest[3 * size_t(v)];
    const double* w = &weights[size_t(v) * H];
    double q[3] = {0, 0, 0};
    for (int i = 0; i < H; ++i) {
      const double* t = T + 12 * i;
      for (int d = 0; d < 3; ++d)
        q[d] += w[i] * (t[4 * d] * p[0] + t[4 * d + 1] * p[1] + t[4 * d + 2] * p[2] + t[4 * d + 3]);
    }
    std::copy(q, q + 3, &out[3 * size_t(v)]);
  }
}

const double* SubdivisionRig::naive(const double* T) {
  blend(rest_cage_, cage_weights_, T, naive_);
  return naive_.data();
}

const double* SubdivisionRig::refine(const double* cage) {
  subdivision_.apply(cage, 3, refined_.data());
  return refined_.data();
}

const double* SubdivisionRig::limit(const double* cage) {
  if (limit_stencils_.rows() != refined_vertex_count()) {
    Subdivision with_edges;
    with_edges.build(mesh_, levels(), true);
    limit_stencils(with_edges.refined_mesh(), limit_stencils_);
    limit_.assign(refined_.size(), 0.0);
  }
  refine(cage);
  using Rows3 = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
  Eigen::Map<Rows3>(limit_.data(), refined_vertex_count(), 3).noalias() =
      limit_stencils_ * Eigen::Map<const Rows3>(refined_.data(), refined_vertex_count(), 3);
  return limit_.data();
}

const double* SubdivisionRig::target(const double* T) {
  blend(rest_refined_, refined_weights_, T, target_);
  return target_.data();
}

double SubdivisionRig::error(const double* cage, const double* T, double* per_vertex) {
  refine(cage);
  target(T);
  double sum = 0, area = 0;
  for (int r = 0; r < refined_vertex_count(); ++r) {
    const double d = (vec3_at(refined_.data(), r) - vec3_at(target_.data(), r)).norm();
    if (per_vertex) per_vertex[r] = d;
    sum += areas_[r] * d * d;
    area += areas_[r];
  }
  return std::sqrt(sum / area) / diagonal_;
}

}  // namespace splinekit::skin3d
