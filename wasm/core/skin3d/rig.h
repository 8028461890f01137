// splinekit — skinning Catmull-Clark subdivision surfaces so that they stay subdivision surfaces.
//
// Liu, Jacobson & Gingold, "Skinning Cubic Bézier Splines and Catmull-Clark Subdivision
// Surfaces", SIGGRAPH Asia 2014, §3.1 (papers/skinning-cubic-bezier-splines-and-catmull-clark.txt):
// the 2D rig's energy (skin/rig.h) with the Bézier basis replaced by the subdivision matrix. The
// surface of cage X is M X (subdivision.h, level k), linear blend skinning moves the rest surface
// to s(p) = Σ_i w_i(p) T_i [p; 1], and the rig finds the cage whose surface is closest to it:
//
//   minimize  ∫ |M X − s(M P)|² dA  ≈  Σ_r D_r |(M X)_r − Σ_i w_ir T_i [p_r; 1]|²,
//
// with D_r the area of refined vertex r (a quarter of each incident refined quad's rest area:
// the quadrature of the continuous energy on the level-k surface). The normal equations
//
//   Â X = Σ_i Ŵ_i T_iᵀ,   Â = Mᵀ D M,   Ŵ_i = Mᵀ D diag(w_i) [P_refined 1]  (#cage by 4)
//
// are solved once per handle column: O = [Â⁻¹ Ŵ_1 … Â⁻¹ Ŵ_H] (#cage by 4H, dense), and a pose is
// X = O · [T_1ᵀ; …; T_Hᵀ], one product into a preallocated buffer. With weights that sum to 1
// the fit reproduces the cage under the identity and any transform shared by every handle.
// M is not always of full rank (the cube's checkerboard subdivides to zero), so Â gets a tiny
// pull of each cage vertex toward its own blend (rig.cpp, precompute).
//
// Baselines (§5): naive = linear blend skinning of the cage vertices, then subdivided; target =
// linear blend skinning of the refined rest surface. Errors are distances per refined vertex and
// their area-weighted RMS over the rest surface's bounding-box diagonal (the fit minimizes exactly
// that RMS, so it is never above the naive one).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <cstddef>
#include <string>
#include <vector>

#include "skin3d/poly_mesh.h"
#include "skin3d/subdivision.h"

namespace splinekit::skin3d {

class SubdivisionRig {
 public:
  // ---- Constructors ---------------------------------------------------------------------------
  // positions: #cage by 3; faces as sizes (#F) and concatenated 0-based indices; creases (0-based
  // vertex pairs); levels in 1..4; handle_count ≥ 1; corner tags (0-based vertices). Builds the
  // cage topology, the subdivision chain, the rest refined surface and its area weights. Returns
  // "" or a message naming the problem (non-finite coordinate, face with a repeated vertex,
  // non-manifold edge, bad crease or corner tag).
  std::string setup(const double* positions, int vertex_count, const int* face_sizes, int face_count,
                    const int* face_indices, const Crease* creases, int crease_count, int levels, int handle_count,
                    const Corner* corners = nullptr, int corner_count = 0);

  // ---- Weights (fill, then precompute) ----------------------------------------------------------
  // Per refined vertex (#refined by #H, row-major) — what the fit integrates — and per cage vertex
  // (#cage by #H) — what the naive baseline blends with.
  std::vector<double>& refined_weights() { return refined_weights_; }
  std::vector<double>& cage_weights() { return cage_weights_; }
  // Shepard weights (skin/shepard.h) of handles at `handles` (#H by 3) at the refined rest vertices
  // and at the cage vertices.
  void use_shepard(const double* handles, double power);
  // Given cage_weights(): refined_weights() = M · cage_weights() (subdivided like positions).
  void prolongate_cage_weights();
  // Given refined_weights(): cage_weights() = the weights of each cage vertex's descendant
  // (refined vertex v < #cage sits where cage vertex v's vertex points converge).
  void restrict_refined_weights();

  // Builds Â, Ŵ, the factorization and O. Returns "" or a message.
  std::string precompute();

  // ---- Queries --------------------------------------------------------------------------------
  // transforms: #H by 12, each a row-major 3×4 [A | t]: x' = A x + t. Writes the fitted cage
  // (#cage by 3) and returns it. Allocation-free.
  const double* update(const double* transforms);
  const std::vector<double>& cage() const { return cage_; }
  // Linear blend skinning of the cage vertices (#cage by 3).
  const double* naive(const double* transforms);
  // M · cage (#refined by 3) into refined().
  const double* refine(const double* cage);
  const std::vector<double>& refined() const { return refined_; }
  // Limit positions of the level-k vertices of M · cage (#refined by 3, limit_stencils); the
  // stencils are built on the first call (it rebuilds the level-k topology).
  const double* limit(const double* cage);
  // Linear blend skinning of the refined rest vertices (#refined by 3).
  const double* target(const double* transforms);
  // Distance of M · cage to the target per refined vertex (into per_vertex, #refined, or null) and
  // the area-weighted RMS of those distances over the bounding-box diagonal of the rest surface.
  double error(const double* cage, const double* transforms, double* per_vertex);

  // ---- Counters -------------------------------------------------------------------------------
  int handle_count() const { return handles_; }
  int levels() const { return subdivision_.levels(); }
  int cage_vertex_count() const { return subdivision_.cage_vertex_count(); }
  int refined_vertex_count() const { return subdivision_.refined_vertex_count(); }
  const std::vector<double>& rest_refined() const { return rest_refined_; }
  const std::vector<double>& rest_cage() const { return rest_cage_; }
  const std::vector<double>& areas() const { return areas_; }
  const std::vector<int>& refined_triangles() const { return triangles_; }
  const Subdivision& subdivision() const { return subdivision_; }
  const PolyMesh& cage_mesh() const { return mesh_; }
  double diagonal() const { return diagonal_; }
  size_t memory_M() const { return subdivision_.memory_bytes(); }
  size_t memory_O() const { return size_t(O_.size()) * sizeof(double); }

 private:
  // LBS of `rest` (count by 3) with `weights` (count by #H) into out.
  void blend(const std::vector<double>& rest, const std::vector<double>& weights, const double* T,
             std::vector<double>& out) const;

  PolyMesh mesh_;
  Subdivision subdivision_;
  int handles_ = 0;
  std::vector<double> rest_cage_, rest_refined_, areas_, refined_weights_, cage_weights_;
  std::vector<int> triangles_;
  double diagonal_ = 1;
  Eigen::MatrixXd O_;                  // #cage by 4H
  std::vector<double> planar_, cage_;  // update scratch (3 planes of #cage) and output
  std::vector<double> naive_, refined_, target_, limit_;
  RowSparse limit_stencils_;
  bool ready_ = false;
};

}  // namespace splinekit::skin3d
