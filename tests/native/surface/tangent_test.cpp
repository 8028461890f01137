// Straightest geodesics, parallel transport, polar coordinates (tangent.h) and the editing gestures
// built on them (edit.h), against closed forms: the plane, the unrolled polyhedral cylinder, and the
// cube, whose corners carry an angle defect of π/2.
#include "surface/tangent.h"
#include "surface/edit.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <tuple>

namespace splinekit::surface {
namespace {

using testing::point_at;

Vec3 pos(const TriMesh& mesh, const MeshPoint& p) { return eval_position(mesh, p); }

int vertex_at(const TriMesh& mesh, const Vec3& x) {
  for (size_t v = 0; v < mesh.positions.size(); ++v)
    if ((mesh.positions[v] - x).norm() < 1e-12) return static_cast<int>(v);
  ADD_FAILURE() << "no vertex at " << x.transpose();
  return 0;
}

// Angle from a to b about the unit normal n (counter-clockwise positive), in (-π, π].
double signed_angle(const Vec3& a, const Vec3& b, const Vec3& n) { return std::atan2(n.dot(a.cross(b)), a.dot(b)); }

double wrap(double a) {  // to (-π, π]
  a = std::fmod(a, 2 * kPi);
  if (a > kPi) a -= 2 * kPi;
  if (a <= -kPi) a += 2 * kPi;
  return a;
}

MeshPoint random_point(const TriMesh& mesh, std::mt19937& rng) {
  std::uniform_int_distribution<int> face(0, static_cast<int>(mesh.triangles.size()) - 1);
  std::uniform_real_distribution<double> u(0, 1);
  double a = u(rng), b = u(rng);
  if (a + b > 1) a = 1 - a, b = 1 - b;
  // Kept off the edges: shrunk towards the centroid.
  return {face(rng), Vec2(0.01 + 0.97 * a, 0.01 + 0.97 * b)};
}

// Every step of a straightest geodesic stays in one face (its two ends lie on a common face).
void expect_steps_share_faces(const TriMesh& mesh, const std::vector<MeshPoint>& points) {
  for (size_t i = 0; i + 1 < points.size(); ++i) {
    std::vector<int> candidates = {points[i].face, points[i + 1].face};
    for (int f : {points[i].face, points[i + 1].face})
      for (int g : mesh.adjacency[f]) candidates.push_back(g);
    for (const MeshPoint& p : {points[i], points[i + 1]})
      if (locate(mesh, p, 1e-7).kind == PointLocation::Kind::kVertex) {
        std::vector<int> fan;
        bool closed;
        vertex_fan(mesh, locate(mesh, p, 1e-7).index, fan, closed);
        candidates.insert(candidates.end(), fan.begin(), fan.end());
      }
    bool shared = false;
    for (int f : candidates) {
      MeshPoint a, b;
      if (f >= 0 && point_in_face(mesh, points[i], f, a, 1e-7) && point_in_face(mesh, points[i + 1], f, b, 1e-7))
        shared = true;
    }
    EXPECT_TRUE(shared) << "steps " << i << ", " << i + 1;
  }
}

// ---- Straightest geodesics ----------------------------------------------------------------------

TEST(SurfaceTangent, StraightestGeodesicIsAStraightLineOnAPlane) {
  const TriMesh mesh = testing::build(testing::planar_grid(40));
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < 100; ++trial) {
    const Vec3 start(0.35 + 0.3 * u(rng), 0.35 + 0.3 * u(rng), 0);
    const double angle = 2 * kPi * u(rng), length = 0.05 + 0.28 * u(rng);
    const Vec3 dir(std::cos(angle), std::sin(angle), 0);
    const MeshPoint p = point_at(mesh, start);
    StraightestGeodesic g;
    straightest_geodesic(mesh, p, {p.face, dir}, length, g);
    EXPECT_FALSE(g.hit_boundary);
    EXPECT_NEAR(g.length, length, 1e-12);
    EXPECT_NEAR((pos(mesh, g.end) - (start + length * dir)).norm(), 0, 1e-9) << "trial " << trial;
    EXPECT_NEAR((g.end_direction.dir - dir).norm(), 0, 1e-9);
    EXPECT_GT(g.points.size(), 4u);  // it crosses faces (cells are 1/40)
    for (const MeshPoint& q : g.points) EXPECT_NEAR((pos(mesh, q) - start).cross(dir).norm(), 0, 1e-9);
    expect_steps_share_faces(mesh, g.points);
  }
}

TEST(SurfaceTangent, StraightestGeodesicStopsAtTheBoundary) {
  const TriMesh mesh = testing::build(testing::planar_grid(10));
  const MeshPoint p = point_at(mesh, Vec3(0.2, 0.3, 0));
  StraightestGeodesic g;
  straightest_geodesic(mesh, p, {p.face, Vec3(0.6, 0.8, 0)}, 5, g);
  EXPECT_TRUE(g.hit_boundary);
  EXPECT_NEAR(g.length, 0.7 / 0.8, 1e-9);  // reaches y = 1 at x = 0.2 + 0.6 * 0.875
  EXPECT_NEAR((pos(mesh, g.end) - Vec3(0.2 + 0.6 * 0.875, 1, 0)).norm(), 0, 1e-9);
}

// The polyhedral cylinder unrolls isometrically onto a strip: height and position along the
// polygon's perimeter are Euclidean coordinates. (Radius 1, `around` sides, height 2.)
struct Cylinder {
  int around = 12, up = 6;
  TriMesh mesh = testing::build(testing::cylinder(around, up, 1, 2));
  double chord() const { return 2 * std::sin(kPi / around); }
  double dz() const { return 2.0 / up; }
  double perimeter() const { return around * chord(); }
  Vec3 corner(int i) const {
    const double phi = 2 * kPi * i / around;
    return {std::cos(phi), std::sin(phi), 0};
  }
  // Unrolled coordinate along the perimeter of a point on the surface (counter-clockwise from x = 1).
  double along(const Vec3& p) const {
    double phi = std::atan2(p.y(), p.x());
    if (phi < 0) phi += 2 * kPi;
    int i = static_cast<int>(std::floor(phi / (2 * kPi / around) + 1e-12)) % around;
    const Vec3 flat(p.x(), p.y(), 0);
    return i * chord() + (flat - corner(i)).norm();
  }
  // The surface point at unrolled coordinates (s, z), and the unit tangent (cos a, sin a) there
  // (a measured from the counter-clockwise horizontal).
  Vec3 at(double s, double z) const {
    s = std::fmod(s, perimeter());
    if (s < 0) s += perimeter();
    const int i = std::min(static_cast<int>(s / chord()), around - 1);
    const double f = (s - i * chord()) / chord();
    return (1 - f) * corner(i) + f * corner(i + 1) + Vec3(0, 0, z);
  }
  // (The horizontal of p's own face: its plane's normal turned a quarter about z, counter-clockwise.)
  Tangent direction(const MeshPoint& p, double a) const {
    const auto& t = mesh.triangles[p.face];
    const Vec3 centroid = (mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]) / 3;
    Vec3 horizontal = Vec3::UnitZ().cross(face_normal(mesh, p.face)).normalized();
    if (horizontal.dot(Vec3::UnitZ().cross(centroid)) < 0) horizontal = -horizontal;
    return {p.face, std::cos(a) * horizontal + std::sin(a) * Vec3::UnitZ()};
  }
  // Compares a traced end with the unrolled expectation (s, z) modulo the perimeter.
  void expect_end(const StraightestGeodesic& g, double s, double z, const char* what) const {
    const Vec3 end = pos(mesh, g.end);
    EXPECT_FALSE(g.hit_boundary) << what;
    EXPECT_NEAR(end.z(), z, 1e-7) << what;
    EXPECT_NEAR(wrap((along(end) - s) / perimeter() * 2 * kPi), 0, 1e-7 / perimeter() * 2 * kPi) << what;
    EXPECT_NEAR(std::hypot(end.x(), end.y()), std::hypot(at(s, z).x(), at(s, z).y()), 1e-9) << what;
  }
};

TEST(SurfaceTangent, StraightestGeodesicUnrollsOnACylinder) {
  const Cylinder cyl;
  const TriMesh& mesh = cyl.mesh;
  // Generic starts and directions (counter-clockwise and clockwise, rising and falling), long
  // enough to wrap around more than once at shallow angles.
  struct Case {
    double s, z, a, length;
  } cases[] = {{0.3, 0.25, 0.3, 5.0},  {2.1, 1.7, -0.4, 3.5},      {4.0, 0.9, 2.0, 1.0},
               {5.5, 0.1, 0.05, 12.0}, {1.0, 1.0, kPi - 0.2, 4.0}, {3.3, 1.9, -1.4, 1.7}};
  for (const Case& c : cases) {
    const MeshPoint p = point_at(mesh, cyl.at(c.s, c.z));
    StraightestGeodesic g;
    straightest_geodesic(mesh, p, cyl.direction(p, c.a), c.length, g);
    cyl.expect_end(g, c.s + c.length * std::cos(c.a), c.z + c.length * std::sin(c.a), "generic");
    EXPECT_NEAR(g.length, c.length, 1e-9);
    expect_steps_share_faces(mesh, g.points);
  }
}

TEST(SurfaceTangent, StraightestGeodesicThroughVerticesOnACylinder) {
  const Cylinder cyl;
  const TriMesh& mesh = cyl.mesh;
  const double c = cyl.chord(), dz = cyl.dz();
  // Horizontal along a ring of vertices (z = 2 dz): from a vertex, and from the middle of a ring edge.
  for (double s0 : {3 * c, 3.5 * c}) {
    const MeshPoint p = point_at(mesh, cyl.at(s0, 2 * dz));
    StraightestGeodesic g;
    straightest_geodesic(mesh, p, cyl.direction(p, 0), 2.5 * cyl.perimeter() / 2, g);
    cyl.expect_end(g, s0 + 2.5 * cyl.perimeter() / 2, 2 * dz, "along a ring");
    for (const MeshPoint& q : g.points) EXPECT_NEAR(pos(mesh, q).z(), 2 * dz, 1e-9);
    // And back the other way.
    straightest_geodesic(mesh, p, cyl.direction(p, kPi), 1.3 * cyl.perimeter(), g);
    cyl.expect_end(g, s0 - 1.3 * cyl.perimeter(), 2 * dz, "along a ring, clockwise");
  }
  // Through vertices across the quads: from vertex (i+1, j) towards vertex (i, j+1) the line crosses
  // the diagonal (i, j)-(i+1, j+1) at its midpoint and meets a vertex every sqrt(c² + dz²).
  {
    const double a = std::atan2(dz, -c), step = std::hypot(c, dz);
    const MeshPoint p = point_at(mesh, cyl.at(5 * c, dz));
    StraightestGeodesic g;
    straightest_geodesic(mesh, p, cyl.direction(p, a), 3.5 * step, g);
    cyl.expect_end(g, 5 * c - 3.5 * c, dz + 3.5 * dz, "vertex to vertex");
    int vertices = 0;
    for (const MeshPoint& q : g.points) vertices += locate(mesh, q, 1e-9).kind == PointLocation::Kind::kVertex;
    EXPECT_GE(vertices, 3);
    expect_steps_share_faces(mesh, g.points);
  }
  // Along the diagonal edges (i, j)-(i+1, j+1) themselves.
  {
    const double a = std::atan2(dz, c), step = std::hypot(c, dz);
    const MeshPoint p = point_at(mesh, cyl.at(7 * c, 0));
    StraightestGeodesic g;
    straightest_geodesic(mesh, p, cyl.direction(p, a), 4.25 * step, g);
    cyl.expect_end(g, 7 * c + 4.25 * c, 4.25 * dz, "along diagonal edges");
  }
}

TEST(SurfaceTangent, StraightestGeodesicAcrossACubeEdgeAndThroughACorner) {
  const TriMesh mesh = testing::build(testing::cube(3));
  // Across the edge x = 1 of the bottom face: unfolding turns the in-plane motion into rising.
  {
    const double a = 0.4, length = 1.1;
    const MeshPoint p = point_at(mesh, Vec3(0.5, 0.2, 0), Vec3(0, 0, -1));
    StraightestGeodesic g;
    straightest_geodesic(mesh, p, {p.face, Vec3(std::cos(a), std::sin(a), 0)}, length, g);
    // Reaches x = 1 after 0.5 / cos a, then climbs the face x = 1.
    const double rest = length - 0.5 / std::cos(a);
    const Vec3 expected(1, 0.2 + length * std::sin(a), rest * std::cos(a));
    EXPECT_NEAR((pos(mesh, g.end) - expected).norm(), 0, 1e-9);
    EXPECT_NEAR((g.end_direction.dir - Vec3(0, std::sin(a), std::cos(a))).norm(), 0, 1e-9);
  }
  // Into the corner (0, 0, 0) along the bottom face's diagonal: the angle sum there is 3π/2, so the
  // geodesic leaves with 3π/4 on either side, which is exactly along the vertical edge x = y = 0.
  {
    const MeshPoint p = point_at(mesh, Vec3(0.3, 0.3, 0), Vec3(0, 0, -1));
    StraightestGeodesic g;
    straightest_geodesic(mesh, p, {p.face, Vec3(-1, -1, 0).normalized()}, 0.3 * std::sqrt(2.0) + 0.5, g);
    EXPECT_NEAR((pos(mesh, g.end) - Vec3(0, 0, 0.5)).norm(), 0, 1e-9);
    EXPECT_NEAR((g.end_direction.dir - Vec3::UnitZ()).norm(), 0, 1e-9);
    // Its turning angle at the corner is 0; turning by 0.2 more on one side gives 0.2.
    const MeshPoint corner = vertex_point(mesh, vertex_at(mesh, Vec3::Zero()));
    const Tangent in{p.face, Vec3(-1, -1, 0).normalized()};
    const MeshPoint up = point_at(mesh, Vec3(0.01, 0.001, 0.2), Vec3(0, -1, 0));
    EXPECT_NEAR(turning_angle(mesh, corner, in, {up.face, Vec3::UnitZ()}), 0, 1e-9);
    EXPECT_NEAR(turning_angle(mesh, corner, in, {up.face, Vec3(std::sin(0.2), 0, std::cos(0.2))}), 0.2, 1e-9);
  }
}

// ---- Parallel transport -------------------------------------------------------------------------

TEST(SurfaceTangent, ParallelTransportOnAPlaneKeepsVectors) {
  const TriMesh mesh = testing::build(testing::planar_grid(20));
  GeodesicSolver solver(mesh);
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(0, 2 * kPi);
  for (int trial = 0; trial < 100; ++trial) {
    const MeshPoint a = random_point(mesh, rng), b = random_point(mesh, rng);
    GeodesicPath path;
    ASSERT_TRUE(solver.shortest_path(a, b, path));
    const double angle = u(rng);
    const Vec3 v(std::cos(angle), std::sin(angle), 0);
    const Tangent moved = parallel_transport(mesh, path, {a.face, v});
    EXPECT_EQ(moved.face, path.strip.back());
    EXPECT_NEAR((moved.dir - v).norm(), 0, 1e-12) << "trial " << trial;
  }
}

// Around the corner (0, 0, 0) of the cube through its three faces: the holonomy of a loop equals
// the enclosed angle defect, 2π − 3·π/2 = π/2.
TEST(SurfaceTangent, ParallelTransportAroundACubeCornerRotatesByTheDefect) {
  const TriMesh mesh = testing::build(testing::cube(4));
  GeodesicSolver solver(mesh);
  // One point on each face at the corner, cyclically symmetric under (x, y, z) -> (z, x, y).
  const Vec3 xa(0.3, 0.2, 0), xb(0, 0.3, 0.2), xc(0.2, 0, 0.3);
  const MeshPoint A = point_at(mesh, xa, Vec3(0, 0, -1)), B = point_at(mesh, xb, Vec3(-1, 0, 0)),
                  C = point_at(mesh, xc, Vec3(0, -1, 0));
  // Each leg crosses one cube edge: unfolded, A -> B is (0.3, 0.2) -> (-0.2, 0.3).
  const double leg = std::hypot(0.5, 0.1);
  auto transport_loop = [&](const std::vector<MeshPoint>& loop, const Vec3& v) {
    Tangent t{loop[0].face, v};
    for (size_t i = 0; i + 1 < loop.size(); ++i) {
      GeodesicPath path;
      EXPECT_TRUE(solver.shortest_path(loop[i], loop[i + 1], path));
      EXPECT_NEAR(path_length(mesh, path), leg, 1e-9);
      t = parallel_transport(mesh, path, t);
    }
    return tangent_in_face(mesh, loop.back(), t, loop.back().face);
  };
  const Vec3 n = face_normal(mesh, A.face);
  ASSERT_NEAR((n - Vec3(0, 0, -1)).norm(), 0, 1e-12);  // outward
  for (double angle : {0.0, 1.0, 2.5}) {
    const Vec3 v(std::cos(angle), std::sin(angle), 0);
    // A -> B -> C runs clockwise seen from outside the corner ((A×B + B×C + C×A)·(-1,-1,-1) < 0):
    // the vector turns clockwise by the defect; the opposite loop turns it back.
    const Tangent cw = transport_loop({A, B, C, A}, v);
    EXPECT_NEAR(signed_angle(v, cw.dir, n), -kPi / 2, 1e-9);
    const Tangent ccw = transport_loop({A, C, B, A}, v);
    EXPECT_NEAR(signed_angle(v, ccw.dir, n), kPi / 2, 1e-9);
  }
  EXPECT_LT(
      xa.cross(xb).dot(Vec3(-1, -1, -1)) + xb.cross(xc).dot(Vec3(-1, -1, -1)) + xc.cross(xa).dot(Vec3(-1, -1, -1)), 0);
}

// ---- Polar coordinates --------------------------------------------------------------------------

TEST(SurfaceTangent, PolarAnglesRoundTripAtFacesEdgesAndVertices) {
  const TriMesh plane = testing::build(testing::planar_grid(8));
  const TriMesh cube = testing::build(testing::cube(2));
  const double angles[] = {0.0, 0.4, 1.3, kPi / 2, 2.9, kPi, 4.1, 5.5, 6.2};
  auto round_trip = [&](const TriMesh& mesh, const MeshPoint& p, const char* what) {
    for (double a : angles) {
      const Tangent t = polar_tangent(mesh, p, a);
      EXPECT_NEAR(t.dir.norm(), 1, 1e-12) << what;
      EXPECT_NEAR(t.dir.dot(face_normal(mesh, t.face)), 0, 1e-12) << what;
      MeshPoint q;
      EXPECT_TRUE(point_in_face(mesh, p, t.face, q, 1e-7)) << what << ": tangent on a face without the point";
      EXPECT_NEAR(wrap(polar_angle(mesh, p, t) - a), 0, 1e-9) << what << " angle " << a;
    }
  };
  // Face points.
  round_trip(plane, {17, Vec2(0.2, 0.3)}, "plane face");
  round_trip(cube, {5, Vec2(0.6, 0.1)}, "cube face");
  // Edge points: the same tangent expressed on the neighbouring face (unfolded across a cube edge)
  // has the same polar angle.
  for (const TriMesh* mesh : {&plane, &cube}) {
    for (int f : {3, 9, 20}) {
      const MeshPoint p{f, Vec2(0.35, 0)};  // on edge (t0, t1)
      ASSERT_EQ(locate(*mesh, p).kind, PointLocation::Kind::kEdge);
      const int g = mesh->adjacency[f][0];
      ASSERT_GE(g, 0);
      round_trip(*mesh, p, "edge");
      for (double a : angles) {
        const Tangent t = polar_tangent(*mesh, p, a);
        const Tangent across = tangent_in_face(*mesh, p, t, g);
        EXPECT_EQ(across.face, g);
        EXPECT_NEAR(across.dir.dot(face_normal(*mesh, g)), 0, 1e-12);
        EXPECT_NEAR(wrap(polar_angle(*mesh, p, across) - a), 0, 1e-9) << "edge, across, angle " << a;
      }
    }
  }
  // Vertex points: a flat interior vertex of the plane, a flat vertex on a cube edge, a cube corner.
  const int flat = plane.mesh_vertex[4 * 9 + 4];  // the grid's centre (file index)
  for (const auto& [mesh, v, what] : {std::tuple<const TriMesh*, int, const char*>{&plane, flat, "plane vertex"},
                                      {&cube, vertex_at(cube, Vec3(0.5, 0, 0)), "cube edge vertex"},
                                      {&cube, vertex_at(cube, Vec3(0, 0, 0)), "cube corner"}}) {
    std::vector<int> fan;
    bool closed;
    vertex_fan(*mesh, v, fan, closed);
    ASSERT_TRUE(closed) << what;
    round_trip(*mesh, vertex_point(*mesh, v), what);
    // The polar angle does not depend on the face the vertex point is expressed on.
    for (int f : fan) {
      MeshPoint on_f;
      ASSERT_TRUE(point_in_face(*mesh, vertex_point(*mesh, v), f, on_f));
      round_trip(*mesh, on_f, what);
    }
  }
  // At a flat vertex polar angles differ by the Euclidean angle; at the cube corner (angle sum 3π/2)
  // the three edges, π/2 apart on the surface, are 2π/3 apart in polar angle.
  {
    const MeshPoint p = vertex_point(plane, flat);
    const Tangent t1 = polar_tangent(plane, p, 0.3), t2 = polar_tangent(plane, p, 2.2);
    EXPECT_NEAR(signed_angle(t1.dir, t2.dir, Vec3::UnitZ()), 1.9, 1e-9);
    const int corner = vertex_at(cube, Vec3::Zero());
    const MeshPoint c = vertex_point(cube, corner);
    std::vector<double> edge_angles;
    for (const Vec3& e : {Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ()}) {
      // A face of the corner's fan whose plane holds the edge direction.
      int face = -1;
      std::vector<int> fan;
      bool closed;
      vertex_fan(cube, corner, fan, closed);
      for (int f : fan)
        if (std::abs(face_normal(cube, f).dot(e)) < 1e-12) face = f;
      ASSERT_GE(face, 0);
      edge_angles.push_back(polar_angle(cube, c, {face, e}));
    }
    std::sort(edge_angles.begin(), edge_angles.end());
    EXPECT_NEAR(edge_angles[1] - edge_angles[0], 2 * kPi / 3, 1e-9);
    EXPECT_NEAR(edge_angles[2] - edge_angles[1], 2 * kPi / 3, 1e-9);
  }
}

TEST(SurfaceTangent, LogAndExpMapsOnAPlane) {
  const TriMesh mesh = testing::build(testing::planar_grid(12));
  GeodesicSolver solver(mesh);
  std::mt19937 rng(12);
  for (int trial = 0; trial < 60; ++trial) {
    // Centres inside faces and at vertices.
    MeshPoint c = random_point(mesh, rng);
    if (trial % 3 == 0) c = vertex_point(mesh, mesh.triangles[c.face][trial % 2 == 0 ? 0 : 2]);
    const MeshPoint x = random_point(mesh, rng);
    const Polar polar = log_map(solver, c, x);
    const Vec3 d = pos(mesh, x) - pos(mesh, c);
    EXPECT_NEAR(polar.radius, d.norm(), 1e-9);
    if (locate(mesh, c).kind == PointLocation::Kind::kFace) {
      // The face frame: x along the face's first edge, y = n × x.
      const auto& t = mesh.triangles[c.face];
      const Vec3 ex = (mesh.positions[t[1]] - mesh.positions[t[0]]).normalized();
      EXPECT_NEAR(wrap(polar.angle - std::atan2(Vec3::UnitZ().cross(ex).dot(d), ex.dot(d))), 0, 1e-9);
    }
    EXPECT_NEAR((pos(mesh, exp_map(mesh, c, polar)) - pos(mesh, x)).norm(), 0, 1e-9) << "trial " << trial;
  }
}

TEST(SurfaceTangent, TurningAngleThroughAFlatVertex) {
  const TriMesh mesh = testing::build(testing::planar_grid(8));
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(0, 2 * kPi);
  int tested = 0;
  for (int v = 0; v < static_cast<int>(mesh.positions.size()); ++v) {
    std::vector<int> fan;
    bool closed;
    vertex_fan(mesh, v, fan, closed);
    if (!closed) continue;
    ++tested;
    const Vec3 pv = mesh.positions[v];
    const double a = u(rng);
    const Vec3 d(std::cos(a), std::sin(a), 0);
    const MeshPoint behind = point_at(mesh, pv - 1e-4 * d), ahead = point_at(mesh, pv + 1e-4 * d);
    const MeshPoint p = vertex_point(mesh, v);
    EXPECT_NEAR(turning_angle(mesh, p, {behind.face, d}, {ahead.face, d}), 0, 1e-9) << "vertex " << v;
    for (double turn : {0.3, -1.1, 2.5}) {
      const Vec3 e(std::cos(a + turn), std::sin(a + turn), 0);
      const MeshPoint next = point_at(mesh, pv + 1e-4 * e);
      EXPECT_NEAR(turning_angle(mesh, p, {behind.face, d}, {next.face, e}), std::abs(turn), 1e-9) << "vertex " << v;
    }
  }
  EXPECT_EQ(tested, 49);
}

// ---- Editing (edit.h) on the plane, where every gesture has its Euclidean meaning ---------------

struct PlaneSpline {
  TriMesh mesh = testing::build(testing::planar_grid(16));
  std::vector<Vec3> xs = {Vec3(0.30, 0.35, 0), Vec3(0.38, 0.52, 0), Vec3(0.42, 0.40, 0), Vec3(0.50, 0.45, 0),
                          Vec3(0.58, 0.50, 0), Vec3(0.62, 0.62, 0), Vec3(0.70, 0.55, 0)};
  std::vector<MeshPoint> points() const {
    std::vector<MeshPoint> out;
    for (const Vec3& x : xs) out.push_back(point_at(mesh, x));
    return out;
  }
};

TEST(SurfaceEdit, MoveAnchorCarriesItsHandlesRigidlyOnAPlane) {
  PlaneSpline s;
  GeodesicSolver solver(s.mesh);
  for (int anchor : {0, 3, 6}) {
    std::vector<MeshPoint> points = s.points();
    const Vec3 to(0.45 + 0.02 * anchor, 0.6 - 0.03 * anchor, 0);
    move_anchor(solver, points, anchor, point_at(s.mesh, to));
    const Vec3 shift = to - s.xs[anchor];
    for (int i = 0; i < 7; ++i) {
      const bool moves = std::abs(i - anchor) <= 1;
      EXPECT_NEAR((pos(s.mesh, points[i]) - (s.xs[i] + (moves ? shift : Vec3::Zero()))).norm(), 0, 1e-9)
          << "anchor " << anchor << " point " << i;
    }
  }
}

TEST(SurfaceEdit, MoveHandleSmoothKeepsTheOppositeHandleOnAPlane) {
  PlaneSpline s;
  GeodesicSolver solver(s.mesh);
  for (int handle : {2, 4}) {
    std::vector<MeshPoint> points = s.points();
    const Vec3 to(0.55, 0.30, 0);
    const int opposite = handle == 2 ? 4 : 2;
    move_handle(solver, points, handle, point_at(s.mesh, to), true);
    const Vec3 a = s.xs[3];
    const Vec3 expected = a - (s.xs[opposite] - a).norm() * (to - a).normalized();
    EXPECT_NEAR((pos(s.mesh, points[handle]) - to).norm(), 0, 1e-12);
    EXPECT_NEAR((pos(s.mesh, points[opposite]) - expected).norm(), 0, 1e-9) << "handle " << handle;
    for (int i : {0, 1, 3, 5, 6}) EXPECT_NEAR((pos(s.mesh, points[i]) - s.xs[i]).norm(), 0, 1e-12);
    // Not smooth: only the handle moves.
    points = s.points();
    move_handle(solver, points, handle, point_at(s.mesh, to), false);
    EXPECT_NEAR((pos(s.mesh, points[opposite]) - s.xs[opposite]).norm(), 0, 1e-12);
  }
}

TEST(SurfaceEdit, MoveHandleSmoothOnACylinderKeepsLengthAndCollinearity) {
  const TriMesh mesh = testing::build(testing::cylinder(24, 8, 1, 2));
  GeodesicSolver solver(mesh);
  auto on = [&](double phi, double z) { return point_at(mesh, Vec3(std::cos(phi), std::sin(phi), z)); };
  std::vector<MeshPoint> points = {on(0.0, 0.5),  on(0.2, 0.7), on(0.4, 0.9), on(0.6, 1.0),
                                   on(0.8, 1.05), on(1.0, 1.2), on(1.2, 1.3)};
  GeodesicPath before;
  solver.shortest_path(points[3], points[2], before);
  move_handle(solver, points, 4, on(0.75, 1.35), true);
  GeodesicPath in, out, keep;
  ASSERT_TRUE(solver.shortest_path(points[2], points[3], in));
  ASSERT_TRUE(solver.shortest_path(points[3], points[4], out));
  ASSERT_TRUE(solver.shortest_path(points[3], points[2], keep));
  EXPECT_NEAR(path_length(mesh, keep), path_length(mesh, before), 1e-9);
  EXPECT_NEAR(turning_angle(mesh, points[3], end_tangent(mesh, in), start_tangent(mesh, out)), 0, 1e-7);
}

TEST(SurfaceEdit, RotateScaleAndTranslateAreEuclideanOnAPlane) {
  PlaneSpline s;
  GeodesicSolver solver(s.mesh);
  const Vec3 center(0.48, 0.47, 0);
  for (double angle : {0.0, 0.7, -2.0, kPi})
    for (double scale : {1.0, 0.6, 1.3}) {
      std::vector<MeshPoint> points = s.points();
      rotate_scale(solver, points, point_at(s.mesh, center), angle, scale);
      const Eigen::Matrix3d R = Eigen::AngleAxisd(angle, Vec3::UnitZ()).toRotationMatrix();
      for (int i = 0; i < 7; ++i)
        EXPECT_NEAR((pos(s.mesh, points[i]) - (center + scale * R * (s.xs[i] - center))).norm(), 0, 1e-9)
            << "angle " << angle << " scale " << scale << " point " << i;
    }
  // Translation from a point to another: every point moves by the same vector, also when the
  // reference points sit on a vertex or far from the spline.
  const std::pair<Vec3, Vec3> moves[] = {{Vec3(0.5, 0.5, 0), Vec3(0.6, 0.3, 0)},
                                         {Vec3(0.2, 0.8, 0), Vec3(0.15, 0.75, 0)},
                                         {s.mesh.positions[s.mesh.triangles[100][1]], Vec3(0.4, 0.41, 0)}};
  for (const auto& [from, to] : moves) {
    std::vector<MeshPoint> points = s.points();
    translate(solver, points, point_at(s.mesh, from), point_at(s.mesh, to));
    for (int i = 0; i < 7; ++i)
      EXPECT_NEAR((pos(s.mesh, points[i]) - (s.xs[i] + to - from)).norm(), 0, 1e-9) << "point " << i;
  }
}

TEST(SurfaceEdit, MapPointsFollowsTheSvgConventionOnAPlane) {
  const TriMesh mesh = testing::build(testing::planar_grid(16));
  const Vec3 center(0.5, 0.5, 0);
  const MeshPoint c = point_at(mesh, center);
  // SVG: x right, y down. With the drawing's up (-y) sent to `up`, x goes to up rotated clockwise
  // by π/2 (seen from the front face, normal +z); then `rotation` turns counter-clockwise.
  const double xy[] = {1, 0, 0, 1, 0, -1, 1.5, -2, -1, 0.5, 0, 0};
  const int count = 6;
  for (const Vec3& up : {Vec3(0, 1, 0), Vec3(1, 1, 0.3), Vec3(-1, 0, 0)})
    for (double rotation : {0.0, 0.4, -2.5}) {
      const double scale = 0.08;
      std::vector<MeshPoint> out;
      map_points(mesh, c, up, rotation, scale, xy, count, out);
      ASSERT_EQ(out.size(), size_t(count));
      const Vec3 u = Vec3(up.x(), up.y(), 0).normalized();
      const Vec3 right = u.cross(Vec3::UnitZ());  // up rotated clockwise
      const Eigen::Matrix3d R = Eigen::AngleAxisd(rotation, Vec3::UnitZ()).toRotationMatrix();
      for (int i = 0; i < count; ++i) {
        const Vec3 expected = center + scale * R * (xy[2 * i] * right - xy[2 * i + 1] * u);
        EXPECT_NEAR((pos(mesh, out[i]) - expected).norm(), 0, 1e-9)
            << "up " << up.transpose() << " rotation " << rotation << " point " << i;
      }
    }
  // No `up`: the drawing's up is the face frame's y axis (polar angle π/2).
  std::vector<MeshPoint> out;
  const double one[] = {0, -1};
  map_points(mesh, c, Vec3::Zero(), 0, 0.1, one, 1, out);
  const Tangent y = polar_tangent(mesh, c, kPi / 2);
  EXPECT_NEAR((pos(mesh, out[0]) - (center + 0.1 * y.dir)).norm(), 0, 1e-9);
}

}  // namespace
}  // namespace splinekit::surface
