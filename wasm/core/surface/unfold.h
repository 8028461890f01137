// A strip of faces laid flat in the plane, face after face across their shared edges: the common
// ground of the funnel algorithm (geodesic.cpp) and of parallel transport (tangent.cpp).
#pragma once

#include "surface/mesh.h"

#include <vector>

namespace splinekit::surface {

struct Portal {
  Vec2 left, right;  // the shared edge's end points, left/right of the direction of travel
  int left_vertex = -1, right_vertex = -1;
};

// A point of a face (barycentrics p.uv) whose corners lie at `c` in the plane.
inline Vec2 on_face(const std::array<Vec2, 3>& c, const MeshPoint& p) {
  return (1 - p.uv.x() - p.uv.y()) * c[0] + p.uv.x() * c[1] + p.uv.y() * c[2];
}

struct UnfoldedStrip {
  std::vector<std::array<Vec2, 3>> corners;  // #strip: 2D positions of each face's corners (t[0], t[1], t[2])
  std::vector<Portal> portals;                // #strip-1
  std::vector<int> faces;

  // A point on strip face i in the plane.
  Vec2 map(int i, const MeshPoint& p) const { return on_face(corners[i], p); }
  // A 3D vector in the plane of strip face i, in the plane (and back).
  Vec2 to_plane(const TriMesh& mesh, int i, const Vec3& v) const;
  Vec3 to_space(const TriMesh& mesh, int i, const Vec2& v) const;
};

// Lays out `strip` (consecutive faces adjacent, consistently wound). Reuses `out`'s storage, and
// the layout in `reuse` (another strip's, not `out`) of the faces it starts with in common.
void unfold_strip(const TriMesh& mesh, const std::vector<int>& strip, UnfoldedStrip& out,
                  const UnfoldedStrip* reuse = nullptr);
// Lays the neighbour of face f across its edge k flat next to f, whose corners lie at `cf`.
void lay_across(const TriMesh& mesh, int f, int k, const std::array<Vec2, 3>& cf, std::array<Vec2, 3>& cg);

}  // namespace splinekit::surface
