#include "surface/unfold.h"

#include <algorithm>
#include <cmath>

namespace splinekit::surface {

namespace {

// Places c so that (a, b, c) winds counter-clockwise, at distances |ac| and |bc|.
Vec2 place_left(const Vec2& a, const Vec2& b, double ac, double bc) {
  const Vec2 ab = b - a;
  const double len = ab.norm();
  if (!(len > 0)) return a + Vec2(0, ac);
  const Vec2 d = ab / len;
  const double x = (ac * ac - bc * bc + len * len) / (2 * len);
  const double y = std::sqrt(std::max(0.0, ac * ac - x * x));
  return a + x * d + y * Vec2(-d.y(), d.x());
}

// Face-local 2D frame of a face: corner 0 at the origin, corner 1 on +x (independent of the strip).
void face_frame(const TriMesh& mesh, int face, Vec3& origin, Vec3& x, Vec3& y) {
  const auto& t = mesh.triangles[face];
  origin = mesh.positions[t[0]];
  const Vec3 e1 = mesh.positions[t[1]] - origin, e2 = mesh.positions[t[2]] - origin;
  x = e1.norm() > 0 ? Vec3(e1.normalized()) : Vec3::UnitX();
  const Vec3 n = e1.cross(e2);
  y = n.norm() > 0 ? Vec3(n.normalized().cross(x)) : x.unitOrthogonal();
}

}  // namespace

void unfold_strip(const TriMesh& mesh, const std::vector<int>& strip, UnfoldedStrip& out) {
  const size_t n = strip.size();
  out.faces = strip;
  out.corners.resize(n);
  out.portals.resize(n > 0 ? n - 1 : 0);
  if (n == 0) return;
  auto length = [&](int a, int b) { return (mesh.positions[a] - mesh.positions[b]).norm(); };
  {
    const auto& t = mesh.triangles[strip[0]];
    auto& c = out.corners[0];
    c[0] = Vec2::Zero();
    c[1] = Vec2(length(t[0], t[1]), 0);
    c[2] = place_left(c[0], c[1], length(t[0], t[2]), length(t[1], t[2]));
  }
  for (size_t i = 0; i + 1 < n; ++i) {
    const int f = strip[i], g = strip[i + 1];
    const int k = edge_to(mesh, f, g);
    const auto& tf = mesh.triangles[f];
    const int a = tf[k], b = tf[(k + 1) % 3];  // a on the right, b on the left of travel
    const Vec2 pa = out.corners[i][k], pb = out.corners[i][(k + 1) % 3];
    out.portals[i] = {pb, pa, b, a};
    const auto& tg = mesh.triangles[g];
    const int ka = corner_of(mesh, g, a), kb = corner_of(mesh, g, b);
    const int kc = 3 - ka - kb;
    auto& c = out.corners[i + 1];
    c[ka] = pa;
    c[kb] = pb;
    // g winds (b, a, c): c is left of b -> a. Its coordinates along and across edge b -> a, as
    // multiples of the edge (the unfolded edge has the same length as in space).
    const Vec3 e = mesh.positions[a] - mesh.positions[b], w = mesh.positions[tg[kc]] - mesh.positions[b];
    const double e2 = e.squaredNorm();
    const Vec2 edge = pa - pb;
    c[kc] = e2 > 0 ? Vec2(pb + (w.dot(e) / e2) * edge + (w.cross(e).norm() / e2) * Vec2(-edge.y(), edge.x()))
                   : place_left(pb, pa, length(b, tg[kc]), length(a, tg[kc]));
  }
}

Vec2 UnfoldedStrip::to_plane(const TriMesh& mesh, int i, const Vec3& v) const {
  // Face frame coordinates, then the rotation that takes the frame's corners to the unfolded ones.
  Vec3 o, x, y;
  face_frame(mesh, faces[i], o, x, y);
  const Vec2 local(v.dot(x), v.dot(y));
  const Vec2 e = corners[i][1] - corners[i][0];
  const double len = e.norm();
  const Vec2 ex = len > 0 ? Vec2(e / len) : Vec2::UnitX();
  return local.x() * ex + local.y() * Vec2(-ex.y(), ex.x());
}

Vec3 UnfoldedStrip::to_space(const TriMesh& mesh, int i, const Vec2& v) const {
  Vec3 o, x, y;
  face_frame(mesh, faces[i], o, x, y);
  const Vec2 e = corners[i][1] - corners[i][0];
  const double len = e.norm();
  const Vec2 ex = len > 0 ? Vec2(e / len) : Vec2::UnitX();
  const Vec2 ey(-ex.y(), ex.x());
  return v.dot(ex) * x + v.dot(ey) * y;
}

}  // namespace splinekit::surface
