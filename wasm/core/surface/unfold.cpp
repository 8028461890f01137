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

// A 3D vector in the plane of `face`, in the plane where the face is laid at `corners`: its face
// frame coordinates, turned by the rotation that takes the frame's corners to the laid ones.
Vec2 vector_to_plane(const TriMesh& mesh, int face, const std::array<Vec2, 3>& corners, const Vec3& v) {
  Vec3 o, x, y;
  face_frame(mesh, face, o, x, y);
  const Vec2 local(v.dot(x), v.dot(y));
  const Vec2 e = corners[1] - corners[0];
  const double len = e.norm();
  const Vec2 ex = len > 0 ? Vec2(e / len) : Vec2::UnitX();
  return local.x() * ex + local.y() * Vec2(-ex.y(), ex.x());
}

}  // namespace

void unfold_strip(const TriMesh& mesh, const std::vector<int>& strip, UnfoldedStrip& out, const UnfoldedStrip* reuse) {
  const size_t n = strip.size();
  // The faces `reuse` laid out at the start of the same strip keep their places.
  size_t known = 0;
  if (reuse) {
    const size_t common = std::min(n, reuse->faces.size());
    while (known < common && reuse->faces[known] == strip[known]) ++known;
  }
  out.faces.clear(), out.corners.clear(), out.portals.clear();
  if (n == 0) return;
  if (known > 0) {
    append_moved(out, *reuse, 0, known, PlaneMotion{});
  } else {
    auto length = [&](int a, int b) { return (mesh.positions[a] - mesh.positions[b]).norm(); };
    const auto& t = mesh.triangles[strip[0]];
    std::array<Vec2, 3> c;
    c[0] = Vec2::Zero();
    c[1] = Vec2(length(t[0], t[1]), 0);
    c[2] = place_left(c[0], c[1], length(t[0], t[2]), length(t[1], t[2]));
    append_face(mesh, out, strip[0], c);
    known = 1;
  }
  for (size_t i = known; i < n; ++i) append_laid(mesh, out, strip[i]);
}

void lay_across(const TriMesh& mesh, int f, int k, const std::array<Vec2, 3>& cf, std::array<Vec2, 3>& cg) {
  const int g = mesh.adjacency[f][k];
  const int a = mesh.triangles[f][k], b = mesh.triangles[f][(k + 1) % 3];
  // g winds (b, a, c) (faces are consistently wound): its edge to f runs from b to a (found by
  // the corners when g meets f along two edges, or its adjacency does not name f).
  const auto& tg = mesh.triangles[g];
  int kb = edge_to(mesh, g, f), ka = (kb + 1) % 3;
  if (kb < 0 || tg[kb] != b || tg[ka] != a) kb = corner_of(mesh, g, b), ka = corner_of(mesh, g, a);
  const int kc = 3 - ka - kb;
  const Vec2 pa = cf[k], pb = cf[(k + 1) % 3], edge = pa - pb;
  cg[ka] = pa;
  cg[kb] = pb;
  // c is left of b -> a: its distances along and across edge b -> a in space, laid along the
  // direction of the laid edge. (Not as multiples of the laid edge: where rounding or an earlier
  // layout made it a little longer or shorter than in space, those multiples would scale every face
  // laid on from there, and a chord's walk of hundreds of faces carried that scale to where it
  // rejoins the strip; each pass's layout then started from the last one's, and the mismatch grew
  // ten times a pass on long coil paths: a funnel path 5e-7 longer in its layout than in space.)
  const int c = tg[kc];
  const Vec3 e = mesh.positions[a] - mesh.positions[b], w = mesh.positions[c] - mesh.positions[b];
  const double e2 = e.squaredNorm(), laid2 = edge.squaredNorm();
  if (!(e2 > 0) || !(laid2 > 0)) {
    cg[kc] = place_left(pb, pa, w.norm(), (mesh.positions[c] - mesh.positions[a]).norm());
    return;
  }
  // 1 / (|e| |laid edge|): 1 / e2 corrected by the ratio r of their squares (its series to r^2;
  // laid edges are within rounding of their length in space but for a layout's drift).
  double inv = 1 / e2;
  const double r = laid2 * inv - 1;
  inv = std::abs(r) < 1e-4 ? inv * (1 - r * (0.5 - 0.375 * r)) : 1 / std::sqrt(e2 * laid2);
  cg[kc] = pb + (w.dot(e) * inv) * edge + (w.cross(e).norm() * inv) * Vec2(-edge.y(), edge.x());
}

bool lay_point(const TriMesh& mesh, int face, const std::array<Vec2, 3>& corners, const Vec3& x, Vec2& out) {
  if (face_normal(mesh, face).isZero()) return false;
  out = corners[0] + vector_to_plane(mesh, face, corners, x - mesh.positions[mesh.triangles[face][0]]);
  return true;
}

PlaneMotion PlaneMotion::between(const std::array<Vec2, 3>& was, const std::array<Vec2, 3>& now) {
  // From the face's longest edge at corner 0 (its length is the same in both layouts).
  const int k = (was[1] - was[0]).squaredNorm() >= (was[2] - was[0]).squaredNorm() ? 1 : 2;
  const Vec2 a = was[k] - was[0], b = now[k] - now[0];
  const double aa = a.squaredNorm();
  PlaneMotion m;
  if (aa > 0) {
    const double c = a.dot(b), s = cross(a, b), len = std::hypot(c, s);
    if (len > 0) m.c = c / len, m.s = s / len;
  }
  // No motion beyond the layouts' rounding (a flat region between the changes): none at all, so
  // that points the layouts agree on (collinear vertices, say) stay exactly where they were.
  const double tiny = 1e-14;
  if (std::abs(m.s) <= tiny && (now[0] - was[0]).norm() <= tiny * (was[0].norm() + std::sqrt(aa))) return PlaneMotion{};
  m.t = now[0] - Vec2(m.c * was[0].x() - m.s * was[0].y(), m.s * was[0].x() + m.c * was[0].y());
  return m;
}

namespace {

// Face `face`, laid at `corners`, entered from u's last face across that face's edge k.
void append_across(const TriMesh& mesh, UnfoldedStrip& u, int k, int face, const std::array<Vec2, 3>& corners) {
  const auto& t = mesh.triangles[u.faces.back()];
  const int k1 = (k + 1) % 3;
  u.portals.push_back(
      {t[k1], t[k], static_cast<int8_t>(k1), static_cast<int8_t>(k)});  // t[k] right, t[k+1] left of travel
  u.faces.push_back(face);
  u.corners.push_back(corners);
}

}  // namespace

void append_face(const TriMesh& mesh, UnfoldedStrip& u, int face, const std::array<Vec2, 3>& corners) {
  if (u.faces.empty()) {
    u.faces.push_back(face);
    u.corners.push_back(corners);
    return;
  }
  append_across(mesh, u, edge_to(mesh, u.faces.back(), face), face, corners);
}

void append_laid(const TriMesh& mesh, UnfoldedStrip& u, int face) {
  const int k = edge_to(mesh, u.faces.back(), face);
  std::array<Vec2, 3> corners;
  lay_across(mesh, u.faces.back(), k, u.corners.back(), corners);
  append_across(mesh, u, k, face, corners);
}

void append_moved(UnfoldedStrip& u, const UnfoldedStrip& src, size_t from, size_t to, const PlaneMotion& m) {
  if (from >= to) return;
  const bool portal_in = !u.faces.empty();
  u.faces.insert(u.faces.end(), src.faces.begin() + from, src.faces.begin() + to);
  u.portals.insert(u.portals.end(), src.portals.begin() + (from - portal_in), src.portals.begin() + (to - 1));
  if (m.identity()) {
    u.corners.insert(u.corners.end(), src.corners.begin() + from, src.corners.begin() + to);
    return;
  }
  // (Phase (iii) moves most of a strip each pass: the motion is copied so that the stores cannot
  // alias it and it is not read again for every corner.)
  const PlaneMotion motion = m;
  u.corners.reserve(u.corners.size() + (to - from));
  for (size_t i = from; i < to; ++i) {
    const std::array<Vec2, 3>& c = src.corners[i];
    u.corners.push_back({motion(c[0]), motion(c[1]), motion(c[2])});
  }
}

void join(const TriMesh& mesh, UnfoldedStrip& u, size_t first) {
  if (first == 0 || first >= u.faces.size()) return;
  const int a = u.portals[first - 1].left_vertex, b = u.portals[first - 1].right_vertex;
  const Vec2 pa = u.left(static_cast<int>(first) - 1), pb = u.right(static_cast<int>(first) - 1);
  for (size_t i = first; i < u.faces.size(); ++i) {
    const auto& t = mesh.triangles[u.faces[i]];
    bool shared = false;
    for (int k = 0; k < 3; ++k) {
      if (t[k] == a) u.corners[i][k] = pa, shared = true;
      if (t[k] == b) u.corners[i][k] = pb, shared = true;
    }
    if (!shared) break;
  }
}

Vec2 UnfoldedStrip::to_plane(const TriMesh& mesh, int i, const Vec3& v) const {
  return vector_to_plane(mesh, faces[i], corners[i], v);
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
