// splinekit — automatic skinning weights on a 2D triangle mesh: harmonic and bounded biharmonic.
//
// Jacobson, Baran, Popović & Sorkine, "Bounded Biharmonic Weights for Real-Time Deformation",
// ACM Transactions on Graphics 30(4), SIGGRAPH 2011. Each handle i gets a weight function w_i,
// piecewise linear over the mesh (one value per vertex), that minimizes the discrete Laplacian
// energy ½ ∫ (Δw_i)² ≈ ½ w_iᵀ (L M⁻¹ L) w_i subject to
//   w_i(handle_j) = δ_ij        (interpolation),
//   0 ≤ w_i ≤ 1                 (bounds: no negative lobes, the "B" of BBW),
// with natural boundary conditions on the mesh boundary; the weights are then normalized to a
// partition of unity (§3 of the paper: optimizing per handle and normalizing stays close to the
// coupled optimum). Harmonic weights (Joshi et al. 2007, the paper's §2 baseline) minimize the
// Dirichlet energy ½ w_iᵀ (−L) w_i under the same interpolation constraints, without bounds.
//
// Liu, Jacobson & Gingold 2014 (§5) mesh the artwork's domain and evaluate these weights at the
// curve samples; the domain is built in src/skin/domain.ts and the weights are read at arbitrary
// points by barycentric interpolation (`locate_and_interpolate`, point_location.h).
//
// The solvers are built from one file each (libigl style): operators.h (cotangent Laplacian, mass
// matrix, gradients), box_qp.h (the bound-constrained QP of one handle, on subset_solver.h and
// supernodal_cholesky.h) and point_location.h.
//
// Conventions: a mesh is a view of flat arrays (mesh_view.h; vertices: #V by 2 doubles x,y;
// triangles: #F by 3 int32 vertex indices, either orientation); weights are #V by #H row-major
// (W[v*#H + i] is the weight of handle i at vertex v); gradients are #·by #H by 2 row-major, like
// shepard.h.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "skin/mesh_view.h"
#include "skin/operators.h"

namespace splinekit::skin {

// ---------------------------------------------------------------------------------------------
// Validation
// ---------------------------------------------------------------------------------------------

// Checks a mesh and its point handles for the weight solvers: at least one triangle, finite
// coordinates, triangle indices in range and distinct, no degenerate (zero-area) triangle, every
// vertex used by a triangle; handles (#H indices into the vertices) at least one, in range and
// distinct; every connected component of the mesh holds a handle (else its weights are
// undetermined). Returns "" when valid, else a message naming the first problem.
std::string validate_weights_input(const MeshView2& mesh, const int32_t* handles, int handle_count);

// ---------------------------------------------------------------------------------------------
// Weights
// ---------------------------------------------------------------------------------------------

// What a solver did. On failure `error` names the problem and the output is untouched.
struct WeightsReport {
  std::string error;            // "" on success
  std::vector<int> iterations;  // BBW: linear solves per handle (1 = the unconstrained solution was feasible)
  bool converged = true;        // BBW: every handle's active set settled within max_iterations
  int pinned = 0;               // BBW: vertices held at a bound to stop an active-set cycle (box_qp.cpp)
  bool ok() const { return error.empty(); }
};

// Harmonic weights: per handle i, minimize w_iᵀ (−L) w_i subject to w_i(handle_j) = δ_ij.
// One factorization of −L restricted to the free vertices serves every handle, and the weights are
// a partition of unity by construction (L·1 = 0). They lie in [0,1] when every cotangent weight is
// non-negative (a Delaunay mesh); otherwise they may overshoot slightly.
//   mesh     the domain
//   handles  #H vertex indices
//   W        output, #V by #H row-major
WeightsReport harmonic_weights(const MeshView2& mesh, const int32_t* handles, int handle_count, double* W);

struct BbwOptions {
  int max_iterations = 100;            // cap on active-set iterations (linear solves) per handle
  double bound_tolerance = 1e-9;       // how far a weight may leave [0,1] and still count as feasible
                                       // (the result is clamped to [0,1] exactly)
  double multiplier_tolerance = 3;     // how negative a bound's multiplier λ_i may be and still keep the
                                       // bound active: |λ_i| ≤ tolerance · √M_ii / area^{3/2}. The scale
                                       // is the weight change such a multiplier error causes along the
                                       // active set's rim (via the bilaplacian's Green's function), so
                                       // the value is unit- and resolution-independent. Smaller is closer
                                       // to the exact optimum and costs more iterations; the default keeps
                                       // weights within ~1e-4 of it on the test and benchmark meshes
                                       // (500 to 20k triangles)
  bool partition_of_unity = true;      // normalize so Σ_i w_i = 1 at every vertex (off: the raw QP optimum)
  MassType mass = MassType::kVoronoi;  // see operators.h
  // Called after each handle's active-set solve with (handles solved, #H), for progress reports;
  // the weights do not depend on it. Unset: not called.
  std::function<void(int, int)> on_handle_solved;
};

// Bounded Biharmonic Weights: per handle i, minimize ½ w_iᵀ Q w_i with Q = L M⁻¹ L subject to
// w_i(handle_j) = δ_ij and 0 ≤ w_i ≤ 1, by a primal-dual active-set method (Hintermüller, Ito &
// Kunisch 2002) started from the unconstrained biharmonic solution, with releases spread over
// neighbouring rings of the active set (box_qp.h). Each iteration fixes the active
// variables at their bounds and solves for the rest with a supernodal sparse Cholesky; the
// fill-reducing ordering is computed once and restricted to each iteration's free set. If a
// handle does not settle within max_iterations, its last iterate is clamped to [0,1] and
// `converged` is false.
//   mesh     the domain
//   handles  #H vertex indices
//   options  see BbwOptions
//   W        output, #V by #H row-major
WeightsReport bbw_weights(const MeshView2& mesh, const int32_t* handles, int handle_count, const BbwOptions& options,
                          double* W);

// The same solver on any domain given its operators (the 3D rig's refined surface, skin3d/weights.h).
// The caller has checked the handles (in range, distinct, one in every connected component).
//   L  #V by #V cotangent Laplacian (cotangent_laplacian)
//   M  #V by #V lumped mass, diagonal and positive (mass_matrix; options.mass is not read)
WeightsReport bbw_weights_from_operators(const Eigen::SparseMatrix<double>& L, const Eigen::SparseMatrix<double>& M,
                                         const int32_t* handles, int handle_count, const BbwOptions& options,
                                         double* W);

}  // namespace splinekit::skin
