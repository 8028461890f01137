// splinekit — point location on a 2D triangle mesh: a uniform grid of triangles, barycentric
// coordinates, the nearest point of a triangle, and interpolation of per-vertex values at
// arbitrary points (how the skinning weights are read at curve samples, Liu, Jacobson & Gingold
// 2014 §5).
//
// Conventions as in mesh_view.h; barycentric coordinates b (3 doubles) are in the order of the
// triangle's vertices: the point is b[0]·v0 + b[1]·v1 + b[2]·v2.
#pragma once

#include <cstdint>
#include <vector>

#include "skin/mesh_view.h"

namespace splinekit::skin {

// ---------------------------------------------------------------------------------------------
// One triangle
// ---------------------------------------------------------------------------------------------

// Barycentric coordinates of (x,y) in triangle t, unclamped (negative outside the triangle).
//   b  output, 3 doubles, summing to 1
void triangle_barycentric(const MeshView2& mesh, int t, double x, double y, double* b);

// The point of triangle t nearest to (x,y).
//   b  output, 3 doubles: its barycentric coordinates (≥ 0, sum 1)
// Returns the squared distance from (x,y) to it (0 inside).
double nearest_on_triangle(const MeshView2& mesh, int t, double x, double y, double* b);

// ---------------------------------------------------------------------------------------------
// The grid
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

// Builds the grid of a (validated, see validate_weights_input) mesh.
//   grid  output
void build_triangle_grid(const MeshView2& mesh, TriangleGrid& grid);

// The triangle holding the (finite) point (x,y) and its barycentric coordinates. A point outside
// the mesh gets the nearest triangle and the barycentric coordinates of the nearest point on it.
//   grid  build_triangle_grid(mesh)
//   bary  output, 3 doubles (≥ 0, sum 1)
int locate_point(const TriangleGrid& grid, const MeshView2& mesh, double x, double y, double* bary);

// ---------------------------------------------------------------------------------------------
// Interpolation at points
// ---------------------------------------------------------------------------------------------

// Per-vertex values at query points, interpolated linearly in the triangle that holds each point.
//   W             #V by #H vertex values (weights), row-major
//   handle_count  #H
//   points        #P by 2
//   out           output, #P by #H row-major
void locate_and_interpolate(const TriangleGrid& grid, const MeshView2& mesh, const double* W, int handle_count,
                            const double* points, int point_count, double* out);

// Per-triangle values at query points: the value of the triangle that holds each point.
//   G             #F by #H by 2 (triangle_weight_gradients, operators.h)
//   handle_count  #H
//   points        #P by 2
//   out           output, #P by #H by 2
void locate_gradients(const TriangleGrid& grid, const MeshView2& mesh, const double* G, int handle_count,
                      const double* points, int point_count, double* out);

}  // namespace splinekit::skin
