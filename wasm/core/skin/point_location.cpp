#include "point_location.h"

#include <algorithm>
#include <cmath>

namespace splinekit::skin {

namespace {

int cell_index(double v, double origin, double cell, int count) {
  const double i = std::floor((v - origin) / cell);
  return !(i > 0) ? 0 : i >= count ? count - 1 : int(i);  // NaN lands in cell 0
}

// Distance from (x,y) to the cells of ring r and beyond: to the part of the grid outside the block
// of cells within Chebyshev distance r−1 of (ci,cj). INFINITY when no such cell is left.
double ring_distance(const TriangleGrid& g, double x, double y, int ci, int cj, int r) {
  if (r == 0) return 0.0;
  const double gx0 = g.x0, gx1 = g.x0 + g.nx * g.cell, gy0 = g.y0, gy1 = g.y0 + g.ny * g.cell;
  const double bx0 = g.x0 + std::max(0, ci - r + 1) * g.cell, bx1 = g.x0 + std::min(g.nx, ci + r) * g.cell;
  const double by0 = g.y0 + std::max(0, cj - r + 1) * g.cell, by1 = g.y0 + std::min(g.ny, cj + r) * g.cell;
  auto to_rect = [&](double x0, double x1, double y0, double y1) {
    const double dx = std::max({x0 - x, 0.0, x - x1}), dy = std::max({y0 - y, 0.0, y - y1});
    return std::sqrt(dx * dx + dy * dy);
  };
  double d = INFINITY;
  if (bx0 > gx0) d = std::min(d, to_rect(gx0, bx0, gy0, gy1));
  if (bx1 < gx1) d = std::min(d, to_rect(bx1, gx1, gy0, gy1));
  if (by0 > gy0) d = std::min(d, to_rect(gx0, gx1, gy0, by0));
  if (by1 < gy1) d = std::min(d, to_rect(gx0, gx1, by1, gy1));
  return d;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// One triangle
// ---------------------------------------------------------------------------------------------

void triangle_barycentric(const MeshView2& m, int t, double x, double y, double* b) {
  const int32_t* f = m.triangle(t);
  const Vec2 a = m.position(f[0]);
  const Vec2 u = m.position(f[1]) - a, v = m.position(f[2]) - a, w = Vec2(x, y) - a;
  const double d = cross(u, v);
  b[1] = cross(w, v) / d;
  b[2] = cross(u, w) / d;
  b[0] = 1.0 - b[1] - b[2];
}

double nearest_on_triangle(const MeshView2& m, int t, double x, double y, double* b) {
  triangle_barycentric(m, t, x, y, b);
  if (b[0] >= 0 && b[1] >= 0 && b[2] >= 0) return 0.0;
  // Outside: the nearest point is on one of the edges (k, k+1).
  const int32_t* f = m.triangle(t);
  const Vec2 X(x, y);
  double best = INFINITY;
  for (int k = 0; k < 3; ++k) {
    const Vec2 p = m.position(f[k]), e = m.position(f[(k + 1) % 3]) - p;
    const double s = std::clamp((X - p).dot(e) / e.squaredNorm(), 0.0, 1.0);
    const double d2 = (p + s * e - X).squaredNorm();
    if (d2 < best) {
      best = d2;
      b[k] = 1.0 - s;
      b[(k + 1) % 3] = s;
      b[(k + 2) % 3] = 0.0;
    }
  }
  return best;
}

// ---------------------------------------------------------------------------------------------
// The grid
// ---------------------------------------------------------------------------------------------

void build_triangle_grid(const MeshView2& m, TriangleGrid& grid) {
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (int v = 0; v < m.vertex_count; ++v)
    for (int a = 0; a < 2; ++a) lo[a] = std::min(lo[a], m.vertex(v)[a]), hi[a] = std::max(hi[a], m.vertex(v)[a]);
  const double w = hi[0] - lo[0], h = hi[1] - lo[1];
  // About one cell per triangle (square cells over the bounding box).
  grid.cell = std::sqrt(w * h / std::max(1, m.triangle_count));
  if (!(grid.cell > 0)) grid.cell = std::max(std::max(w, h), 1e-300);
  grid.x0 = lo[0];
  grid.y0 = lo[1];
  grid.nx = std::max(1, int(std::ceil(w / grid.cell)));
  grid.ny = std::max(1, int(std::ceil(h / grid.cell)));

  // Two passes over the triangles' bounding boxes: count per cell, then fill (CSR).
  const size_t cells = size_t(grid.nx) * grid.ny;
  grid.start.assign(cells + 1, 0);
  auto for_cells = [&](int t, auto&& visit) {
    const int32_t* f = m.triangle(t);
    double tlo[2] = {INFINITY, INFINITY}, thi[2] = {-INFINITY, -INFINITY};
    for (int k = 0; k < 3; ++k)
      for (int a = 0; a < 2; ++a)
        tlo[a] = std::min(tlo[a], m.vertex(f[k])[a]), thi[a] = std::max(thi[a], m.vertex(f[k])[a]);
    const int i0 = cell_index(tlo[0], grid.x0, grid.cell, grid.nx),
              i1 = cell_index(thi[0], grid.x0, grid.cell, grid.nx);
    const int j0 = cell_index(tlo[1], grid.y0, grid.cell, grid.ny),
              j1 = cell_index(thi[1], grid.y0, grid.cell, grid.ny);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) visit(size_t(j) * grid.nx + i);
  };
  for (int t = 0; t < m.triangle_count; ++t) for_cells(t, [&](size_t c) { ++grid.start[c + 1]; });
  for (size_t c = 0; c < cells; ++c) grid.start[c + 1] += grid.start[c];
  grid.items.resize(size_t(grid.start[cells]));
  std::vector<int32_t> fill(grid.start.begin(), grid.start.end() - 1);
  for (int t = 0; t < m.triangle_count; ++t) for_cells(t, [&](size_t c) { grid.items[fill[c]++] = t; });
}

int locate_point(const TriangleGrid& grid, const MeshView2& m, double x, double y, double* bary) {
  const int ci = cell_index(x, grid.x0, grid.cell, grid.nx), cj = cell_index(y, grid.y0, grid.cell, grid.ny);
  // Inside: a triangle of the point's cell contains it (up to rounding, which is clamped away).
  const size_t c = size_t(cj) * grid.nx + ci;
  for (int32_t e = grid.start[c]; e < grid.start[c + 1]; ++e) {
    const int t = grid.items[e];
    triangle_barycentric(m, t, x, y, bary);
    if (bary[0] >= -1e-12 && bary[1] >= -1e-12 && bary[2] >= -1e-12) {
      for (int k = 0; k < 3; ++k) bary[k] = std::max(bary[k], 0.0);
      const double sum = bary[0] + bary[1] + bary[2];
      for (int k = 0; k < 3; ++k) bary[k] /= sum;
      return t;
    }
  }
  // Outside: the nearest triangle, searching rings of cells outwards (ring r: the cells at
  // Chebyshev distance r from the point's cell, clamped into the grid) until no unvisited cell
  // can be nearer than the best triangle so far.
  int best = -1;
  double best_d2 = INFINITY, b[3];
  for (int r = 0;; ++r) {
    const double reach = ring_distance(grid, x, y, ci, cj, r);
    if (reach == INFINITY || (best >= 0 && best_d2 <= reach * reach)) break;
    for (int j = std::max(0, cj - r); j <= std::min(grid.ny - 1, cj + r); ++j) {
      const bool edge_row = j == cj - r || j == cj + r;
      for (int i = std::max(0, ci - r); i <= std::min(grid.nx - 1, ci + r); ++i) {
        if (!edge_row && i != ci - r && i != ci + r) continue;  // inside the ring: seen before
        const size_t cc = size_t(j) * grid.nx + i;
        for (int32_t e = grid.start[cc]; e < grid.start[cc + 1]; ++e) {
          const int t = grid.items[e];
          const double d2 = nearest_on_triangle(m, t, x, y, b);
          if (d2 < best_d2) {
            best_d2 = d2;
            best = t;
            std::copy(b, b + 3, bary);
          }
        }
      }
    }
  }
  return best;
}

// ---------------------------------------------------------------------------------------------
// Interpolation at points
// ---------------------------------------------------------------------------------------------

void locate_and_interpolate(const TriangleGrid& grid, const MeshView2& m, const double* W, int handle_count,
                            const double* points, int point_count, double* out) {
  double b[3];
  for (int p = 0; p < point_count; ++p) {
    const int t = locate_point(grid, m, points[2 * p], points[2 * p + 1], b);
    const int32_t* f = m.triangle(t);
    const double *w0 = W + size_t(f[0]) * handle_count, *w1 = W + size_t(f[1]) * handle_count,
                 *w2 = W + size_t(f[2]) * handle_count;
    double* o = out + size_t(p) * handle_count;
    for (int i = 0; i < handle_count; ++i) o[i] = b[0] * w0[i] + b[1] * w1[i] + b[2] * w2[i];
  }
}

void locate_gradients(const TriangleGrid& grid, const MeshView2& m, const double* G, int handle_count,
                      const double* points, int point_count, double* out) {
  double b[3];
  const size_t stride = 2 * size_t(handle_count);
  for (int p = 0; p < point_count; ++p) {
    const int t = locate_point(grid, m, points[2 * p], points[2 * p + 1], b);
    std::copy(G + size_t(t) * stride, G + size_t(t + 1) * stride, out + size_t(p) * stride);
  }
}

}  // namespace splinekit::skin
