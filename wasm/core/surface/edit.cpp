#include "surface/edit.h"

#include <cmath>

namespace splinekit::surface {

namespace {

// The handle at `handle` as (direction at the anchor, length).
struct Arm {
  Tangent dir;
  double length = 0;
};

Arm arm(GeodesicSolver& solver, const MeshPoint& anchor, const MeshPoint& handle) {
  GeodesicPath path;
  solver.shortest_path(anchor, handle, path);
  return {start_tangent(solver.mesh(), path), path_length(solver.mesh(), path)};
}

MeshPoint shoot(const TriMesh& mesh, const MeshPoint& from, const Tangent& dir, double length) {
  if (!(length > 0) || dir.dir.norm() == 0) return from;
  StraightestGeodesic out;
  straightest_geodesic(mesh, from, dir, length, out);
  return out.end;
}

bool is_anchor(int i) { return i % 3 == 0; }

}  // namespace

Polar log_map(GeodesicSolver& solver, const MeshPoint& c, const MeshPoint& x) {
  const Arm a = arm(solver, c, x);
  if (a.dir.dir.norm() == 0) return {0, 0};
  return {a.length, polar_angle(solver.mesh(), c, a.dir)};
}

MeshPoint exp_map(const TriMesh& mesh, const MeshPoint& c, const Polar& polar) {
  if (!(polar.radius > 0)) return c;
  return shoot(mesh, c, polar_tangent(mesh, c, polar.angle), polar.radius);
}

void move_anchor(GeodesicSolver& solver, std::vector<MeshPoint>& points, int anchor, const MeshPoint& to) {
  const TriMesh& mesh = solver.mesh();
  const MeshPoint from = points[anchor];
  GeodesicPath motion;
  solver.shortest_path(from, to, motion);
  for (int h : {anchor - 1, anchor + 1}) {
    if (h < 0 || h >= static_cast<int>(points.size())) continue;
    const Arm a = arm(solver, from, points[h]);
    // The transported direction lives on the path's last face, where motion.end expresses `to`.
    const Tangent moved = parallel_transport(mesh, motion, a.dir);
    points[h] = a.dir.dir.norm() == 0 || motion.strip.empty() ? to : shoot(mesh, motion.end, moved, a.length);
  }
  points[anchor] = to;
}

void move_handle(GeodesicSolver& solver, std::vector<MeshPoint>& points, int handle, const MeshPoint& to, bool smooth) {
  points[handle] = to;
  if (!smooth || is_anchor(handle)) return;
  const int anchor = handle % 3 == 1 ? handle - 1 : handle + 1;
  const int opposite = 2 * anchor - handle;
  if (opposite < 0 || opposite >= static_cast<int>(points.size())) return;
  const double keep = arm(solver, points[anchor], points[opposite]).length;
  const Arm moved = arm(solver, points[anchor], to);
  if (moved.dir.dir.norm() == 0) return;
  points[opposite] = shoot(solver.mesh(), points[anchor], {moved.dir.face, -moved.dir.dir}, keep);
}

void make_smooth(GeodesicSolver& solver, std::vector<MeshPoint>& points, int anchor) {
  const int before = anchor - 1, after = anchor + 1;
  if (before < 0 || after >= static_cast<int>(points.size())) return;
  const Arm in = arm(solver, points[anchor], points[before]);
  const Arm out = arm(solver, points[anchor], points[after]);
  if (in.dir.dir.norm() == 0 || out.dir.dir.norm() == 0) return;
  // Both arms turn to the bisector of the corner so that neither jumps.
  const TriMesh& mesh = solver.mesh();
  const double a = polar_angle(mesh, points[anchor], in.dir);
  const double b = polar_angle(mesh, points[anchor], out.dir);
  double gap = std::fmod(b - a - kPi, 2 * kPi);  // how far `out` is from opposite `in`
  if (gap > kPi) gap -= 2 * kPi;
  if (gap < -kPi) gap += 2 * kPi;
  const double ain = a + 0.5 * gap, aout = ain + kPi;
  points[before] = exp_map(mesh, points[anchor], {in.length, ain});
  points[after] = exp_map(mesh, points[anchor], {out.length, aout});
}

void rotate_scale(GeodesicSolver& solver, std::vector<MeshPoint>& points, const MeshPoint& c, double angle,
                  double scale) {
  std::vector<Polar> polar(points.size());
  for (size_t i = 0; i < points.size(); ++i) polar[i] = log_map(solver, c, points[i]);
  for (size_t i = 0; i < points.size(); ++i)
    points[i] = exp_map(solver.mesh(), c, {polar[i].radius * scale, polar[i].angle + angle});
}

void translate(GeodesicSolver& solver, std::vector<MeshPoint>& points, const MeshPoint& from, const MeshPoint& to) {
  const TriMesh& mesh = solver.mesh();
  std::vector<Polar> polar(points.size());
  for (size_t i = 0; i < points.size(); ++i) polar[i] = log_map(solver, from, points[i]);
  // The frame at `from` carried to `to`: its x axis lands at polar angle `turn` there.
  GeodesicPath motion;
  solver.shortest_path(from, to, motion);
  const Tangent x_axis = polar_tangent(mesh, from, 0);
  const Tangent carried = parallel_transport(mesh, motion, x_axis);
  const double turn = motion.strip.empty() ? 0 : polar_angle(mesh, motion.end, carried);
  for (size_t i = 0; i < points.size(); ++i) points[i] = exp_map(mesh, to, {polar[i].radius, polar[i].angle + turn});
}

void map_points(const TriMesh& mesh, const MeshPoint& center, const Vec3& up, double rotation, double scale,
                const double* xy, int count, std::vector<MeshPoint>& out) {
  // Polar angle of the drawing's up direction.
  double base = kPi / 2;
  {
    const Vec3 n = face_normal(mesh, center.face);
    const Vec3 t = up - n * up.dot(n);
    if (t.norm() > 1e-12 * std::max(1.0, up.norm())) base = polar_angle(mesh, center, {center.face, t.normalized()});
  }
  out.resize(count);
  for (int i = 0; i < count; ++i) {
    const double x = xy[2 * i] * scale, w = -xy[2 * i + 1] * scale;  // w: up in the drawing
    const double r = std::hypot(x, w);
    const double angle = base + rotation + std::atan2(w, x) - kPi / 2;
    out[i] = exp_map(mesh, center, {r, angle});
  }
}

}  // namespace splinekit::surface
