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
// points by barycentric interpolation (`locate_and_interpolate`).
//
// Conventions: a mesh is a view of flat arrays (vertices: #V by 2 doubles x,y; triangles: #F by 3
// int32 vertex indices, either orientation); weights are #V by #H row-major (W[v*#H + i] is the
// weight of handle i at vertex v); gradients are #·by #H by 2 row-major, like shepard.h.
#pragma once

#include <Eigen/SparseCore>
#include <cstdint>
#include <string>
#include <vector>

namespace splinekit::skin {

// A 2D triangle mesh in caller-owned flat arrays (no ownership, no copy).
struct MeshView2 {
  const double* vertices = nullptr;   // #V by 2: x,y
  int vertex_count = 0;               // #V
  const int32_t* triangles = nullptr; // #F by 3: vertex indices
  int triangle_count = 0;             // #F
};

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
// Discrete operators
// ---------------------------------------------------------------------------------------------

// Cotangent Laplacian L (#V by #V, symmetric, negative semi-definite, rows sum to 0):
// L_ij = ½ (cot α_ij + cot β_ij) over the angles opposite edge ij, L_ii = −Σ_j L_ij.
void cotangent_laplacian(const MeshView2& mesh, Eigen::SparseMatrix<double>& L);

// Which lumped mass matrix. The numbers cross to TS (src/skin/weights.ts passes 0 or 1).
enum class MassType : int {
  kBarycentric = 0,  // a third of each incident triangle's area
  kVoronoi = 1,      // mixed Voronoi areas (Meyer et al. 2003): circumcentric cells, obtuse triangles split ½, ¼, ¼
};

// Lumped (diagonal) mass matrix M (#V by #V); its diagonal sums to the mesh area for both types.
void mass_matrix(const MeshView2& mesh, MassType type, Eigen::SparseMatrix<double>& M);

// ---------------------------------------------------------------------------------------------
// Weights
// ---------------------------------------------------------------------------------------------

// What a solver did. On failure `error` names the problem and the output is untouched.
struct WeightsReport {
  std::string error;            // "" on success
  std::vector<int> iterations;  // BBW: linear solves per handle (1 = the unconstrained solution was feasible)
  bool converged = true;        // BBW: every handle's active set settled within max_iterations
  int pinned = 0;               // BBW: vertices held at a bound to stop an active-set cycle (weights.cpp)
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
  int max_iterations = 100;           // cap on active-set iterations (linear solves) per handle
  double bound_tolerance = 1e-9;      // how far a weight may leave [0,1] and still count as feasible
                                      // (the result is clamped to [0,1] exactly)
  double multiplier_tolerance = 3;    // how negative a bound's multiplier λ_i may be and still keep the
                                      // bound active: |λ_i| ≤ tolerance · √M_ii / area^{3/2}. The scale
                                      // is the weight change such a multiplier error causes along the
                                      // active set's rim (via the bilaplacian's Green's function), so
                                      // the value is unit- and resolution-independent. Smaller is closer
                                      // to the exact optimum and costs more iterations; the default keeps
                                      // weights within ~1e-4 of it on the test and benchmark meshes
                                      // (500 to 20k triangles)
  bool partition_of_unity = true;     // normalize so Σ_i w_i = 1 at every vertex (off: the raw QP optimum)
  MassType mass = MassType::kVoronoi;
};

// Bounded Biharmonic Weights: per handle i, minimize ½ w_iᵀ Q w_i with Q = L M⁻¹ L subject to
// w_i(handle_j) = δ_ij and 0 ≤ w_i ≤ 1, by a primal-dual active-set method (Hintermüller, Ito &
// Kunisch 2002) started from the unconstrained biharmonic solution, with releases spread over
// neighbouring rings of the active set (see weights.cpp). Each iteration fixes the active
// variables at their bounds and solves for the rest with a supernodal sparse Cholesky; the
// fill-reducing ordering is computed once and restricted to each iteration's free set. If a
// handle does not settle within max_iterations, its last iterate is clamped to [0,1] and
// `converged` is false.
//   mesh     the domain
//   handles  #H vertex indices
//   options  see BbwOptions
//   W        output, #V by #H row-major
WeightsReport bbw_weights(const MeshView2& mesh, const int32_t* handles, int handle_count,
                          const BbwOptions& options, double* W);

// Gradients of the piecewise-linear weights, constant per triangle (for the Jacobian baseline).
//   W  #V by #H weights
//   G  output, #F by #H by 2 (G[(t*#H + i)*2 + axis])
void triangle_weight_gradients(const MeshView2& mesh, const double* W, int handle_count, double* G);

// ---------------------------------------------------------------------------------------------
// Point location and interpolation
// ---------------------------------------------------------------------------------------------

// A uniform grid over the mesh's bounding box; each cell lists the triangles whose bounding box
// overlaps it (CSR). About one cell per triangle. Build once per mesh, then query many points.
struct TriangleGrid {
  double x0 = 0, y0 = 0;       // lower-left corner of cell (0,0)
  double cell = 1;             // cell side length
  int nx = 0, ny = 0;          // cells along x and y
  std::vector<int32_t> start;  // nx·ny + 1 offsets into `items`; cell (i,j) is cell j·nx + i
  std::vector<int32_t> items;  // triangle indices, cell after cell
};

// Builds the grid of a (validated) mesh.
void build_triangle_grid(const MeshView2& mesh, TriangleGrid& grid);

// The triangle holding the (finite) point (x,y) and its barycentric coordinates (bary: 3 doubles, ≥ 0, sum 1,
// in the order of the triangle's vertices). A point outside the mesh gets the nearest triangle and
// the barycentric coordinates of the nearest point on it.
int locate_point(const TriangleGrid& grid, const MeshView2& mesh, double x, double y, double* bary);

// Weights at query points, interpolated linearly in the triangle that holds each point.
//   W        #V by #H vertex weights
//   points   #P by 2
//   out      output, #P by #H row-major
void locate_and_interpolate(const TriangleGrid& grid, const MeshView2& mesh, const double* W, int handle_count,
                            const double* points, int point_count, double* out);

// Gradients at query points: the gradient of the triangle that holds each point.
//   G        #F by #H by 2 (triangle_weight_gradients)
//   points   #P by 2
//   out      output, #P by #H by 2
void locate_gradients(const TriangleGrid& grid, const MeshView2& mesh, const double* G, int handle_count,
                      const double* points, int point_count, double* out);

}  // namespace splinekit::skin
