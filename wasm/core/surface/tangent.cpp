#include "surface/tangent.h"

#include "surface/unfold.h"

#include <algorithm>
#include <cmath>

namespace splinekit::surface {

namespace {

// The corner of face f at vertex v: unit first edge e (towards t[k+1]), its in-plane perpendicular y
// (towards the corner's inside), and the corner angle.
struct Corner {
  Vec3 e, y;
  double angle = 0;
};

Corner corner(const TriMesh& mesh, int f, int v) {
  const auto& t = mesh.triangles[f];
  const int k = corner_of(mesh, f, v);
  const Vec3& p = mesh.positions[v];
  const Vec3 a = mesh.positions[t[(k + 1) % 3]] - p, b = mesh.positions[t[(k + 2) % 3]] - p;
  Corner c;
  c.e = a.norm() > 0 ? Vec3(a.normalized()) : Vec3::UnitX();
  Vec3 n = a.cross(b);
  c.y = n.norm() > 0 ? Vec3(n.normalized().cross(c.e)) : c.e.unitOrthogonal();
  c.angle = std::atan2(a.cross(b).norm(), a.dot(b));
  return c;
}

// The fan of a vertex with the cumulative angle at which each face's corner starts.
struct Fan {
  std::vector<int> faces;
  std::vector<double> start;  // #faces + 1; start.back() = angle sum
  bool closed = false;
  double total() const { return start.back(); }
  int index_of(int f) const {
    const auto it = std::find(faces.begin(), faces.end(), f);
    return it == faces.end() ? -1 : static_cast<int>(it - faces.begin());
  }
};

void build_fan(const TriMesh& mesh, int v, Fan& fan) {
  vertex_fan(mesh, v, fan.faces, fan.closed);
  fan.start.assign(1, 0.0);
  for (int f : fan.faces) fan.start.push_back(fan.start.back() + corner(mesh, f, v).angle);
}

// Fan angle (unscaled) of direction d lying in the plane of face f at vertex v.
double fan_angle(const TriMesh& mesh, const Fan& fan, int v, int f, const Vec3& d) {
  const Corner c = corner(mesh, f, v);
  const int i = std::max(fan.index_of(f), 0);
  double phi = fan.start[i] + std::atan2(d.dot(c.y), d.dot(c.e));
  if (fan.closed) {
    phi = std::fmod(phi, fan.total());
    if (phi < 0) phi += fan.total();
  } else {
    phi = std::clamp(phi, 0.0, fan.total());
  }
  return phi;
}

// The unit direction at fan angle phi, on the face whose corner holds it (or on face g if given).
Tangent fan_direction(const TriMesh& mesh, const Fan& fan, int v, double phi, int g = -1) {
  int i = g >= 0 ? fan.index_of(g) : -1;
  if (i < 0) {
    i = static_cast<int>(fan.faces.size()) - 1;
    for (size_t j = 0; j < fan.faces.size(); ++j)
      if (phi < fan.start[j + 1]) {
        i = static_cast<int>(j);
        break;
      }
  }
  double local = phi - fan.start[i];
  if (fan.closed && g >= 0) {  // the representative of phi nearest to g's corner
    const double total = fan.total(), mid = 0.5 * (fan.start[i + 1] - fan.start[i]);
    while (local - mid > 0.5 * total) local -= total;
    while (local - mid < -0.5 * total) local += total;
  }
  const Corner c = corner(mesh, fan.faces[i], v);
  return {fan.faces[i], std::cos(local) * c.e + std::sin(local) * c.y};
}

// Unit in-plane normal of edge k of face f pointing into f.
Vec3 inward(const TriMesh& mesh, int f, int k) {
  const auto& t = mesh.triangles[f];
  const Vec3& a = mesh.positions[t[k]];
  const Vec3 e = mesh.positions[t[(k + 1) % 3]] - a;
  const Vec3 c = mesh.positions[t[(k + 2) % 3]] - a;
  const double el = e.squaredNorm();
  const Vec3 m = el > 0 ? Vec3(c - e * (c.dot(e) / el)) : c;
  return m.norm() > 0 ? Vec3(m.normalized()) : Vec3::Zero();
}

// A direction in face f carried across its edge k into the neighbouring face (unfolding).
Vec3 across_edge(const TriMesh& mesh, int f, int k, const Vec3& d) {
  const int g = mesh.adjacency[f][k];
  const auto& t = mesh.triangles[f];
  const Vec3 e = (mesh.positions[t[(k + 1) % 3]] - mesh.positions[t[k]]).normalized();
  const int kg = edge_to(mesh, g, f);
  // The component along the edge stays; the one leaving f becomes the one entering g.
  return d.dot(e) * e - d.dot(inward(mesh, f, k)) * inward(mesh, g, kg);
}

// Gradients of the barycentric coordinates of face f (3D vectors in its plane).
void barycentric_gradients(const TriMesh& mesh, int f, Vec3 grad[3]) {
  const auto& t = mesh.triangles[f];
  const Vec3& p0 = mesh.positions[t[0]];
  const Vec3& p1 = mesh.positions[t[1]];
  const Vec3& p2 = mesh.positions[t[2]];
  const Vec3 n = (p1 - p0).cross(p2 - p0);
  const double a2 = n.squaredNorm();
  if (!(a2 > 0)) {
    grad[0] = grad[1] = grad[2] = Vec3::Zero();
    return;
  }
  grad[0] = n.cross(p2 - p1) / a2;
  grad[1] = n.cross(p0 - p2) / a2;
  grad[2] = n.cross(p1 - p0) / a2;
}

}  // namespace

Tangent tangent_in_face(const TriMesh& mesh, const MeshPoint& p, const Tangent& t, int g) {
  if (t.face == g) return t;
  const PointLocation where = locate(mesh, p, 1e-7);
  if (where.kind == PointLocation::Kind::kVertex) {
    Fan fan;
    build_fan(mesh, where.index, fan);
    if (fan.index_of(t.face) < 0 || fan.index_of(g) < 0) return {g, t.dir};
    return fan_direction(mesh, fan, where.index, fan_angle(mesh, fan, where.index, t.face, t.dir), g);
  }
  const int k = edge_to(mesh, t.face, g);
  if (k >= 0) return {g, across_edge(mesh, t.face, k, t.dir)};
  return {g, t.dir};
}

double polar_angle(const TriMesh& mesh, const MeshPoint& p, const Tangent& t) {
  const PointLocation where = locate(mesh, p, 1e-7);
  if (where.kind == PointLocation::Kind::kVertex) {
    Fan fan;
    build_fan(mesh, where.index, fan);
    const int f = fan.index_of(t.face) >= 0 ? t.face : fan.faces.front();
    const double phi = fan_angle(mesh, fan, where.index, f, t.dir);
    return fan.closed && fan.total() > 0 ? phi * (2 * kPi / fan.total()) : phi;
  }
  const Tangent local = tangent_in_face(mesh, p, t, p.face);
  const auto& tr = mesh.triangles[p.face];
  const Vec3 x = (mesh.positions[tr[1]] - mesh.positions[tr[0]]).normalized();
  const Vec3 y = face_normal(mesh, p.face).cross(x);
  double angle = std::atan2(local.dir.dot(y), local.dir.dot(x));
  if (angle < 0) angle += 2 * kPi;
  return angle;
}

Tangent polar_tangent(const TriMesh& mesh, const MeshPoint& p, double angle) {
  const PointLocation where = locate(mesh, p, 1e-7);
  if (where.kind == PointLocation::Kind::kVertex) {
    Fan fan;
    build_fan(mesh, where.index, fan);
    double phi = angle;
    if (fan.closed) {
      phi = std::fmod(angle, 2 * kPi);
      if (phi < 0) phi += 2 * kPi;
      phi *= fan.total() / (2 * kPi);
    } else {
      phi = std::clamp(phi, 0.0, fan.total());
    }
    return fan_direction(mesh, fan, where.index, phi);
  }
  const auto& tr = mesh.triangles[p.face];
  const Vec3 x = (mesh.positions[tr[1]] - mesh.positions[tr[0]]).normalized();
  const Vec3 y = face_normal(mesh, p.face).cross(x);
  return {p.face, std::cos(angle) * x + std::sin(angle) * y};
}

double turning_angle(const TriMesh& mesh, const MeshPoint& p, const Tangent& in, const Tangent& out) {
  const PointLocation where = locate(mesh, p, 1e-7);
  if (where.kind == PointLocation::Kind::kVertex) {
    Fan fan;
    build_fan(mesh, where.index, fan);
    if (fan.index_of(in.face) >= 0 && fan.index_of(out.face) >= 0) {
      const double back = fan_angle(mesh, fan, where.index, in.face, -in.dir);
      const double ahead = fan_angle(mesh, fan, where.index, out.face, out.dir);
      if (fan.closed) {
        double left = std::fmod(ahead - back, fan.total());
        if (left < 0) left += fan.total();
        return std::abs(left - 0.5 * fan.total());
      }
      return std::abs(kPi - std::abs(ahead - back));
    }
  }
  const Tangent a = tangent_in_face(mesh, p, in, out.face);
  const double c = a.dir.cross(out.dir).norm(), d = a.dir.dot(out.dir);
  return std::atan2(c, d);
}

void straightest_geodesic(const TriMesh& mesh, const MeshPoint& p, const Tangent& dir, double length,
                          StraightestGeodesic& out) {
  out.points.clear();
  out.hit_boundary = false;
  out.length = 0;
  MeshPoint cur = p;
  Tangent d = dir;
  if (d.face != cur.face) point_in_face(mesh, p, d.face, cur, 1e-7);
  if (d.dir.norm() > 0) d.dir.normalize();
  out.points.push_back(cur);
  out.end = cur;
  out.end_direction = d;
  if (!(length > 0) || d.dir.norm() == 0) return;

  // At a vertex start, begin on the face whose corner holds the direction.
  {
    const PointLocation where = locate(mesh, cur, 1e-7);
    if (where.kind == PointLocation::Kind::kVertex) {
      Fan fan;
      build_fan(mesh, where.index, fan);
      if (fan.index_of(d.face) >= 0) {
        d = fan_direction(mesh, fan, where.index, fan_angle(mesh, fan, where.index, d.face, d.dir));
        point_in_face(mesh, cur, d.face, cur, 1e-7);
      }
    }
  }

  constexpr double kVertexEps = 1e-7;
  double remaining = length;
  int entry_edge = -1;
  bool leaving_vertex = locate(mesh, cur, kVertexEps).kind == PointLocation::Kind::kVertex;
  Vec3 grad[3];
  const size_t guard = 4 * mesh.triangles.size() + 64;
  for (size_t step = 0; step < guard; ++step) {
    const int f = cur.face;
    barycentric_gradients(mesh, f, grad);
    Eigen::Vector3d w = weights(cur);
    const Eigen::Vector3d dw(grad[0].dot(d.dir), grad[1].dot(d.dir), grad[2].dot(d.dir));
    double s_exit = std::numeric_limits<double>::infinity();
    const bool from_vertex = leaving_vertex;
    leaving_vertex = false;
    int exit_corner = -1;  // the barycentric coordinate that reaches 0
    for (int i = 0; i < 3; ++i) {
      if (dw[i] >= 0) continue;
      const int edge = (i + 1) % 3;
      const double s = std::max(w[i], 0.0) / -dw[i];
      if (edge == entry_edge && s < 1e-12 * mesh.scale) continue;
      if (from_vertex && w[i] <= 0) continue;  // the edges at the vertex just left
      if (s < s_exit) s_exit = s, exit_corner = i;
    }
    if (exit_corner < 0 || s_exit >= remaining) {  // ends inside this face
      const double s = exit_corner < 0 ? 0 : remaining;
      w += s * dw;
      w = w.cwiseMax(0.0);
      w /= w.sum();
      cur = from_weights(f, w);
      out.length += s;
      break;
    }
    w += s_exit * dw;
    w[exit_corner] = 0;
    w = w.cwiseMax(0.0);
    w /= w.sum();
    remaining -= s_exit;
    out.length += s_exit;
    cur = from_weights(f, w);
    out.points.push_back(cur);
    // Through a vertex: leave with half the angle sum on either side.
    int vertex_corner = -1;
    for (int i = 0; i < 3; ++i)
      if (w[i] > 1 - kVertexEps) vertex_corner = i;
    if (vertex_corner >= 0) {
      const int v = mesh.triangles[f][vertex_corner];
      Fan fan;
      build_fan(mesh, v, fan);
      if (!fan.closed) {
        out.hit_boundary = true;
        break;
      }
      const double back = fan_angle(mesh, fan, v, f, -d.dir);
      double ahead = std::fmod(back + 0.5 * fan.total(), fan.total());
      d = fan_direction(mesh, fan, v, ahead);
      Eigen::Vector3d wv = Eigen::Vector3d::Zero();
      wv[corner_of(mesh, d.face, v)] = 1;
      cur = from_weights(d.face, wv);
      entry_edge = -1;
      leaving_vertex = true;
      continue;
    }
    const int k = (exit_corner + 1) % 3;  // the edge opposite the corner that reached 0
    const int g = mesh.adjacency[f][k];
    if (g < 0) {
      out.hit_boundary = true;
      break;
    }
    d.dir = across_edge(mesh, f, k, d.dir).normalized();
    d.face = g;
    point_in_face(mesh, cur, g, cur, 1e-9);
    if (cur.face != g) {  // numerical guard: rebuild the point from the edge
      const auto& t = mesh.triangles[f];
      Eigen::Vector3d wg = Eigen::Vector3d::Zero();
      wg[corner_of(mesh, g, t[k])] = w[k];
      wg[corner_of(mesh, g, t[(k + 1) % 3])] = w[(k + 1) % 3];
      cur = from_weights(g, wg / wg.sum());
    }
    entry_edge = edge_to(mesh, g, f);
  }
  out.points.push_back(cur);
  out.end = cur;
  out.end_direction = d;
}

Tangent parallel_transport(const TriMesh& mesh, const GeodesicPath& path, const Tangent& v) {
  if (path.strip.empty()) return v;
  const Tangent first = tangent_in_face(mesh, path.start, v, path.strip.front());
  if (path.strip.size() == 1) return first;
  static thread_local UnfoldedStrip unfolded;
  unfold_strip(mesh, path.strip, unfolded);
  const Vec2 planar = unfolded.to_plane(mesh, 0, first.dir);
  return {path.strip.back(), unfolded.to_space(mesh, static_cast<int>(path.strip.size()) - 1, planar)};
}

}  // namespace splinekit::surface
