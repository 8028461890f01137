#include "surface/path.h"

#include <algorithm>
#include <cmath>

namespace splinekit::surface {

void remove_loops(std::vector<int>& strip, std::vector<int>& face_marks) {
  size_t out = 0;
  for (size_t i = 0; i < strip.size(); ++i) {
    const int f = strip[i];
    if (face_marks[f] >= 0) {
      for (size_t j = face_marks[f] + 1; j < out; ++j) face_marks[strip[j]] = -1;
      out = face_marks[f] + 1;
      continue;
    }
    face_marks[f] = static_cast<int>(out);
    strip[out++] = f;
  }
  strip.resize(out);
  for (int f : strip) face_marks[f] = -1;
}

void grow_faces(const TriMesh& mesh, const std::vector<int>& faces, double width, std::vector<int>& face_marks,
                std::vector<int>& out) {
  auto centroid = [&](int f) {
    const auto& t = mesh.triangles[f];
    return Vec3((mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]) / 3);
  };
  // face_marks: the face of `faces` each face was reached from.
  out.clear();
  for (int f : faces)
    if (face_marks[f] < 0) face_marks[f] = f, out.push_back(f);
  const double reach = width * width;
  for (size_t i = 0; i < out.size(); ++i) {
    const int seed = face_marks[out[i]];
    const Vec3 from = centroid(seed);
    for (int g : mesh.adjacency[out[i]])
      if (g >= 0 && face_marks[g] < 0 && (centroid(g) - from).squaredNorm() <= reach)
        face_marks[g] = seed, out.push_back(g);
  }
  for (int f : out) face_marks[f] = -1;
}

namespace {

// Crossing i of a path as weights on face strip[i + side] (side 0: its own face, 1: the next one).
MeshPoint crossing_point(const TriMesh& mesh, const GeodesicPath& path, size_t i, int side) {
  const int f = path.strip[i];
  const int g = path.strip[i + 1];
  const int k = edge_to(mesh, f, g);
  const double l = path.lerps[i];
  Eigen::Vector3d w = Eigen::Vector3d::Zero();
  if (side == 0) {
    w[k] = 1 - l;
    w[(k + 1) % 3] = l;
    return from_weights(f, w);
  }
  w[corner_of(mesh, g, mesh.triangles[f][k])] = 1 - l;
  w[corner_of(mesh, g, mesh.triangles[f][(k + 1) % 3])] = l;
  return from_weights(g, w);
}

// Point j of the path (0: start, 1..n-1: crossings, n: end) expressed on strip[j] (or the last face).
MeshPoint point_on_own_face(const TriMesh& mesh, const GeodesicPath& path, size_t j) {
  if (j == 0) return path.start;
  if (j > path.lerps.size()) return path.end;
  return crossing_point(mesh, path, j - 1, 1);
}
// Point j+1 expressed on strip[j].
MeshPoint next_point_on_face(const TriMesh& mesh, const GeodesicPath& path, size_t j) {
  if (j >= path.lerps.size()) return path.end;
  return crossing_point(mesh, path, j, 0);
}

}  // namespace

void path_points(const TriMesh& mesh, const GeodesicPath& path, std::vector<MeshPoint>& points) {
  points.clear();
  points.push_back(path.start);
  for (size_t i = 0; i < path.lerps.size(); ++i) points.push_back(crossing_point(mesh, path, i, 0));
  points.push_back(path.end);
}

void path_positions(const TriMesh& mesh, const GeodesicPath& path, std::vector<Vec3>& positions) {
  positions.clear();
  positions.push_back(eval_position(mesh, path.start));
  for (size_t i = 0; i < path.lerps.size(); ++i)
    positions.push_back(eval_position(mesh, crossing_point(mesh, path, i, 0)));
  positions.push_back(eval_position(mesh, path.end));
}

double path_length(const TriMesh& mesh, const GeodesicPath& path) {
  Vec3 prev = eval_position(mesh, path.start);
  double length = 0;
  for (size_t i = 0; i < path.lerps.size(); ++i) {
    const Vec3 p = eval_position(mesh, crossing_point(mesh, path, i, 0));
    length += (p - prev).norm();
    prev = p;
  }
  return length + (eval_position(mesh, path.end) - prev).norm();
}

namespace {

// The arc length of a path at each of its points (start, crossings, end): the path's own, or measured
// into `at`.
const std::vector<double>& arc_lengths(const TriMesh& mesh, const GeodesicPath& path, std::vector<double>& at) {
  if (path.arc.size() == path.lerps.size() + 2) return path.arc;
  static thread_local std::vector<Vec3> positions;
  path_positions(mesh, path, positions);
  at.resize(positions.size());
  at[0] = 0;
  for (size_t j = 1; j < positions.size(); ++j) at[j] = at[j - 1] + (positions[j] - positions[j - 1]).norm();
  return at;
}

// Locates arc-length fraction t: segment j (between points j and j+1, on face strip[j]) and the
// fraction within it.
void locate_fraction(const std::vector<double>& at, double t, size_t& segment, double& alpha) {
  const size_t segments = at.size() - 1;
  const double target = std::clamp(t, 0.0, 1.0) * at.back();
  for (size_t j = 0; j < segments; ++j) {
    const double len = at[j + 1] - at[j];
    if (at[j + 1] >= target && len > 0) {
      segment = j;
      alpha = std::clamp((target - at[j]) / len, 0.0, 1.0);
      return;
    }
  }
  segment = segments - 1;
  alpha = 1;
}

MeshPoint lerp_on_segment(const TriMesh& mesh, const GeodesicPath& path, size_t j, double alpha) {
  const MeshPoint p = point_on_own_face(mesh, path, j);
  const MeshPoint q = next_point_on_face(mesh, path, j);
  return {p.face, (1 - alpha) * p.uv + alpha * q.uv};
}

}  // namespace

MeshPoint eval_path(const TriMesh& mesh, const GeodesicPath& path, double t) {
  if (path.strip.empty()) return path.start;
  static thread_local std::vector<double> scratch;
  const std::vector<double>& at = arc_lengths(mesh, path, scratch);
  size_t j;
  double alpha;
  locate_fraction(at, t, j, alpha);
  return lerp_on_segment(mesh, path, j, alpha);
}

GeodesicPath sub_path(const TriMesh& mesh, const GeodesicPath& path, double t0, double t1) {
  if (path.strip.empty()) return path;
  static thread_local std::vector<double> scratch;
  const std::vector<double>& at = arc_lengths(mesh, path, scratch);
  size_t j0, j1;
  double a0, a1;
  locate_fraction(at, t0, j0, a0);
  locate_fraction(at, t1, j1, a1);
  GeodesicPath out;
  out.start = lerp_on_segment(mesh, path, j0, a0);
  out.end = lerp_on_segment(mesh, path, j1, a1);
  out.strip.assign(path.strip.begin() + j0, path.strip.begin() + j1 + 1);
  out.lerps.assign(path.lerps.begin() + j0, path.lerps.begin() + j1);
  // Its arc lengths: the path's from its start point on.
  const double s0 = at[j0] + a0 * (at[j0 + 1] - at[j0]), s1 = at[j1] + a1 * (at[j1 + 1] - at[j1]);
  out.arc.resize(out.lerps.size() + 2);
  out.arc[0] = 0;
  for (size_t k = 1; k <= out.lerps.size(); ++k) out.arc[k] = at[j0 + k] - s0;
  out.arc.back() = std::max(s1 - s0, out.arc[out.lerps.size()]);
  return out;
}

GeodesicPath reversed(const TriMesh&, const GeodesicPath& path) {
  GeodesicPath out;
  out.start = path.end;
  out.end = path.start;
  out.strip.assign(path.strip.rbegin(), path.strip.rend());
  out.lerps.resize(path.lerps.size());
  for (size_t i = 0; i < path.lerps.size(); ++i) out.lerps[i] = 1 - path.lerps[path.lerps.size() - 1 - i];
  if (!path.arc.empty()) {
    out.arc.resize(path.arc.size());
    const double total = path.arc.back();
    for (size_t k = 0; k < path.arc.size(); ++k) out.arc[k] = total - path.arc[path.arc.size() - 1 - k];
  }
  return out;
}

Tangent start_tangent(const TriMesh& mesh, const GeodesicPath& path) {
  if (path.strip.empty()) return {path.start.face, Vec3::Zero()};
  const Vec3 p0 = eval_position(mesh, path.start);
  const double eps = 1e-12 * mesh.scale;
  for (size_t j = 0; j + 1 < path.strip.size() + 1; ++j) {
    const Vec3 q = eval_position(mesh, next_point_on_face(mesh, path, j));
    const Vec3 d = q - p0;
    if (d.norm() > eps) return {path.strip[j], d.normalized()};
  }
  return {path.start.face, Vec3::Zero()};
}

Tangent end_tangent(const TriMesh& mesh, const GeodesicPath& path) {
  if (path.strip.empty()) return {path.end.face, Vec3::Zero()};
  const Vec3 p1 = eval_position(mesh, path.end);
  const double eps = 1e-12 * mesh.scale;
  for (size_t j = path.strip.size(); j-- > 0;) {
    const Vec3 q = eval_position(mesh, point_on_own_face(mesh, path, j));
    const Vec3 d = p1 - q;
    if (d.norm() > eps) return {path.strip[j], d.normalized()};
  }
  return {path.end.face, Vec3::Zero()};
}

}  // namespace splinekit::surface
