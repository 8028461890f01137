// splinekit — discrete operators on a 2D triangle mesh: the cotangent Laplacian, the lumped mass
// matrix and the gradients of piecewise-linear functions.
//
// The operators of the skinning weights (weights.h): the Dirichlet energy ½ wᵀ(−L)w of harmonic
// weights and the bilaplacian energy ½ wᵀ(L M⁻¹ L)w of bounded biharmonic weights (Jacobson,
// Baran, Popović & Sorkine 2011, §3), as libigl's cotmatrix.h and massmatrix.h define them.
#pragma once

#include <Eigen/SparseCore>

#include "skin/mesh_view.h"

namespace splinekit::skin {

// Cotangent Laplacian L (#V by #V, symmetric, negative semi-definite, rows sum to 0):
// L_ij = ½ (cot α_ij + cot β_ij) over the angles opposite edge ij, L_ii = −Σ_j L_ij.
//   mesh  the domain (valid: see validate_weights_input)
//   L     output, #V by #V
void cotangent_laplacian(const MeshView2& mesh, Eigen::SparseMatrix<double>& L);
// The same on a triangulated surface in 3D (angles and areas measured in 3D).
void cotangent_laplacian_3d(const MeshView3& mesh, Eigen::SparseMatrix<double>& L);

// Which lumped mass matrix. The numbers cross to TS (src/skin/weights.ts passes 0 or 1).
enum class MassType : int {
  kBarycentric = 0,  // a third of each incident triangle's area
  kVoronoi = 1,      // mixed Voronoi areas (Meyer et al. 2003): circumcentric cells, obtuse triangles split ½, ¼, ¼
};

// Lumped (diagonal) mass matrix M; its diagonal sums to the mesh area for both types.
//   mesh  the domain
//   type  see MassType
//   M     output, #V by #V diagonal
void mass_matrix(const MeshView2& mesh, MassType type, Eigen::SparseMatrix<double>& M);
void mass_matrix_3d(const MeshView3& mesh, MassType type, Eigen::SparseMatrix<double>& M);

// Gradients of the piecewise-linear functions W (one per column), constant per triangle (for the
// Jacobian baseline of the skinning rig).
//   mesh          the domain
//   W             #V by #H, row-major: W[v*#H + i]
//   handle_count  #H
//   G             output, #F by #H by 2, row-major: G[(t*#H + i)*2 + axis]
void triangle_weight_gradients(const MeshView2& mesh, const double* W, int handle_count, double* G);

}  // namespace splinekit::skin
