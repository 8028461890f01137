// splinekit — Catmull-Clark subdivision as sparse matrices: cage → level-k refined vertices.
//
// Catmull & Clark 1978 for polygons of any size and vertices of any valence, with boundaries and
// semi-sharp creases in OpenSubdiv's shape-file convention (DeRose, Kass & Truong 1998, as
// simplified by OpenSubdiv's uniform scheme). Liu, Jacobson & Gingold 2014 (§3.1) only need the
// subdivision to be linear: refined = M · cage, M = S_k ⋯ S_1, one sparse S_j per level.
//
// One level (parent → child): child vertices are ordered [vertex points (#V), edge points (#E),
// face points (#F)], so child vertex v < #V descends from parent vertex v; each n-gon becomes n
// quads (vertex point, edge point, face point, previous edge point), keeping its orientation.
//   face point    F = mean of the face's vertices
//   edge point    smooth: (v0 + v1 + F_a + F_b) / 4; sharp (s ≥ 1, or a boundary): (v0 + v1) / 2;
//                 0 < s < 1: (1 − s)·smooth + s·sharp
//   vertex point  by the number k of sharp edges (s > 0; boundary edges are +∞) at the vertex:
//                 k ≤ 1 smooth: ((n − 2) v + Σ_edges e_j / n + Σ_faces F_j / n) / n (n = valence);
//                 k = 2 crease: (6 v + a + b) / 8 (a, b the other ends of the two sharp edges);
//                 k ≥ 3, or a boundary vertex of a single face: corner, v itself.
//                 A crease or corner whose sharp edges have mean sharpness s̄ < 1 is blended
//                 (1 − s̄)·smooth + s̄·(crease or corner) — a simplification of OpenSubdiv's
//                 fractional transition; infinitely sharp and boundary edges give s̄ ≥ 1.
//                 A corner tag (vertex sharpness s_v > 0, OpenSubdiv's `t corner`) makes the
//                 vertex point a·v + (1 − a)·(the rule above), a = min(1, s_v): a corner for as
//                 many levels as s_v (the child vertex point gets s_v − 1, +∞ stays).
//   child edges   the two halves of a parent edge get sharpness s − 1 (clamped at 0; +∞ stays);
//                 edges inside a face are smooth.
// Boundaries are therefore cubic B-spline curves of the boundary polygon with corners (vertices of
// one face) kept, and sharp creases stay sharp for as many levels as their sharpness.
#pragma once

#include <Eigen/SparseCore>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "skin3d/poly_mesh.h"

namespace splinekit::skin3d {

using RowSparse = Eigen::SparseMatrix<double, Eigen::RowMajor>;

// One level of Catmull-Clark: the child mesh (with edges and sharpness when with_topology, else
// faces only) and the matrix S (#child vertices by #parent vertices), child = S · parent.
void refine_once(const PolyMesh& parent, RowSparse& S, PolyMesh& child, bool with_topology);

// Limit positions of a mesh's vertices (a mesh of quads with topology and sharpness, e.g. the
// level-k mesh of Subdivision::build(…, final_topology = true)): limit = L · vertices, with the
// Catmull-Clark limit masks (Halstead, Kass & DeRose 1993): smooth vertex of valence n:
// (n² v + 4 Σ edge neighbours + Σ diagonal neighbours) / (n (n + 5)); crease (two sharp edges):
// (a + 4 v + b) / 6; corner (three or more, or a boundary vertex of one face): v; blended with
// the smooth mask by the mean sharpness of the sharp edges when it is below 1, as in refine_once.
void limit_stencils(const PolyMesh& quads, RowSparse& L);

// The chain S_1 … S_k from a cage to its level-k refinement, kept factored (memory: Σ nnz(S_j),
// far below the product M's on large cages), with the level-k faces (all quads).
class Subdivision {
 public:
  // ---- Constructors ---------------------------------------------------------------------------
  // cage: a PolyMesh with topology and crease sharpness (make_poly_mesh + apply_creases);
  // levels ≥ 1. Builds every S_j; with final_topology the level-k mesh also gets its edges and
  // their (decayed) crease sharpness, to be used as a cage of its own.
  void build(const PolyMesh& cage, int levels, bool final_topology = false);

  // ---- Queries --------------------------------------------------------------------------------
  int levels() const { return int(steps_.size()); }
  int cage_vertex_count() const { return cage_vertices_; }
  int refined_vertex_count() const { return int(steps_.empty() ? cage_vertices_ : steps_.back().rows()); }
  const RowSparse& step(int j) const { return steps_[size_t(j)]; }  // S_{j+1}
  const PolyMesh& refined_mesh() const { return refined_; }         // level-k faces (quads), no edges

  // refined (#refined by cols, row-major) = M · cage (#cage by cols, row-major). Uses internal
  // scratch sized on first use for cols (allocation-free afterwards for the same cols).
  void apply(const double* cage, int cols, double* refined);
  // Mᵀ · G (#cage by cols) for the #refined by cols matrix G given row by row: row(r, g) writes
  // row r of G into g (cols values). G is never stored: each row goes straight through S_kᵀ.
  Eigen::MatrixXd apply_transpose(int cols, const std::function<void(int, double*)>& row) const;
  // The lower triangle (column-major, diagonal included) of Mᵀ D M for the diagonal D (#refined),
  // a #cage by #cage sparse matrix: what the rig factorizes. Assembled from small dense blocks,
  // one per cage face: each level-k vertex is owned by the first cage face whose level-k quads
  // contain it (vertices of no quad, i.e. descendants of cage vertices no face uses, form groups
  // of their own), so Mᵀ D M = Σ_f M_fᵀ D_f M_f over the rows M_f of the vertices f owns. M_f is
  // dense over the few cage vertices C_f that reach them (a face's 1-ring): the chain restricted
  // to the vertices in between, S_k[R_f, ·] ⋯ S_1[·, C_f], multiplied out into dense rows. The
  // product of the whole chain over the finest level (gram below) is never formed.
  Eigen::SparseMatrix<double> gram_lower(const Eigen::VectorXd& D) const;
  // The rig's normal equations in one pass: returns gram_lower(D) and writes MtG = Mᵀ G (#cage by
  // width) for G given row by row as in apply_transpose (with width = 0, MtG is left alone). Each
  // group's rows of G go through its copy of S_k at hand; S_(k−1)ᵀ … S_1ᵀ follow level by level.
  Eigen::SparseMatrix<double> normal_equations(const Eigen::VectorXd& D, int width,
                                               const std::function<void(int, double*)>& row,
                                               Eigen::MatrixXd& MtG) const;
  // Mᵀ D M in full by sparse products, level by level: S_1ᵀ(S_2ᵀ(⋯ S_kᵀ D S_k ⋯)S_2)S_1. The
  // reference construction (tests compare gram_lower against it); slower and far larger in
  // memory on big cages.
  Eigen::SparseMatrix<double> gram(const Eigen::VectorXd& D) const;
  // The product M, explicitly (for tests and small cages).
  RowSparse compose() const;
  // Bytes held by the factored M: values and indices of every S_j.
  size_t memory_bytes() const;

 private:
  int cage_vertices_ = 0;
  std::vector<int> cage_face_start_;  // the cage's face offsets: face f's level-k quads are contiguous
  std::vector<RowSparse> steps_;
  PolyMesh refined_;
  std::vector<Eigen::MatrixXd> scratch_;  // per intermediate level: cols by #rows, i.e. #rows by cols row-major
};

}  // namespace splinekit::skin3d
