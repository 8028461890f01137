// A strip of faces laid flat in the plane, face after face across their shared edges: the common
// ground of the funnel algorithm (funnel.cpp) and of parallel transport (tangent.cpp).
#pragma once

#include "surface/mesh.h"

#include <vector>

namespace splinekit::surface {

// The edge between strip faces i and i+1: its end points are corners of face i (the end points'
// places are those corners', so moving a layout moves only corners).
struct Portal {
  int left_vertex = -1, right_vertex = -1;   // left/right of the direction of travel
  int8_t left_corner = 0, right_corner = 0;  // their corners in face i
};

// A point of a face (barycentrics p.uv) whose corners lie at `c` in the plane.
inline Vec2 on_face(const std::array<Vec2, 3>& c, const MeshPoint& p) {
  return (1 - p.uv.x() - p.uv.y()) * c[0] + p.uv.x() * c[1] + p.uv.y() * c[2];
}

struct UnfoldedStrip {
  std::vector<std::array<Vec2, 3>> corners;  // #strip: 2D positions of each face's corners (t[0], t[1], t[2])
  std::vector<Portal> portals;               // #strip-1
  std::vector<int> faces;

  // A point on strip face i in the plane.
  Vec2 map(int i, const MeshPoint& p) const { return on_face(corners[i], p); }
  // The end points of portal i in the plane.
  const Vec2& left(int i) const { return corners[i][portals[i].left_corner]; }
  const Vec2& right(int i) const { return corners[i][portals[i].right_corner]; }
  // A 3D vector in the plane of strip face i, in the plane (and back).
  Vec2 to_plane(const TriMesh& mesh, int i, const Vec3& v) const;
  Vec3 to_space(const TriMesh& mesh, int i, const Vec2& v) const;
};

// Lays out `strip` (consecutive faces adjacent, consistently wound). Reuses `out`'s storage, and
// the layout in `reuse` (another strip's, not `out`) of the faces it starts with in common.
void unfold_strip(const TriMesh& mesh, const std::vector<int>& strip, UnfoldedStrip& out,
                  const UnfoldedStrip* reuse = nullptr);

// A rigid motion of the plane: x -> R x + t, R the rotation by the angle of cosine c, sine s.
struct PlaneMotion {
  double c = 1, s = 0;
  Vec2 t = Vec2::Zero();
  bool identity() const { return c == 1 && s == 0 && t.x() == 0 && t.y() == 0; }
  // (Written on whole columns so that both coordinates are moved at once where the target has SIMD;
  // lane by lane it is (c x - s y + t_x, s x + c y + t_y), rounded alike.)
  Vec2 operator()(const Vec2& x) const { return Vec2(c, s) * x.x() + Vec2(-s, c) * x.y() + t; }
  std::array<Vec2, 3> operator()(const std::array<Vec2, 3>& c3) const {
    return {(*this)(c3[0]), (*this)(c3[1]), (*this)(c3[2])};
  }
  // The motion that takes a face laid at `was` to the same face laid at `now`.
  static PlaneMotion between(const std::array<Vec2, 3>& was, const std::array<Vec2, 3>& now);
};

// A strip laid out piece by piece from layouts already known (phase (iii)'s trial strips, which
// keep most of the current strip's faces, moved rigidly, and lay only where they changed). Each
// appends to `u` after its last face (the first of a strip starts it).
//
// Face `face` laid at `corners` (continuing the layout of u's last face).
void append_face(const TriMesh& mesh, UnfoldedStrip& u, int face, const std::array<Vec2, 3>& corners);
// Face `face` laid flat across its edge with u's last face.
void append_laid(const TriMesh& mesh, UnfoldedStrip& u, int face);
// Faces [from, to) of `src` moved by m (u's last face is src's face from-1, or u is empty and from 0).
void append_moved(UnfoldedStrip& u, const UnfoldedStrip& src, size_t from, size_t to, const PlaneMotion& m);
// Makes the faces from `first` on meet face first-1 exactly at the two vertices they share with it
// (in every face up to the first face without them; portals read their corners): pieces laid or
// moved separately meet only up to rounding, and the funnel takes a vertex for one point only where
// it is one.
void join(const TriMesh& mesh, UnfoldedStrip& u, size_t first);

// Where the point x of space lies in the plane of face `face` laid at `corners`: the point of the
// face's plane nearest to x, laid with the face (x itself for a point of the face). False for a
// degenerate face.
bool lay_point(const TriMesh& mesh, int face, const std::array<Vec2, 3>& corners, const Vec3& x, Vec2& out);

// Lays the neighbour of face f across its edge k flat next to f, whose corners lie at `cf`.
void lay_across(const TriMesh& mesh, int f, int k, const std::array<Vec2, 3>& cf, std::array<Vec2, 3>& cg);

}  // namespace splinekit::surface
