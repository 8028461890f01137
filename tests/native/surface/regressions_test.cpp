// Regressions: splitting exactly at a leaf boundary, and the OLR adaptive polygon doubling back.
#include <gtest/gtest.h>
#include "surface/curves.h"
#include "surface/tangent.h"
#include "test_meshes.h"
namespace splinekit::surface {
namespace {
using Poly = std::array<Vec3, 4>;
using testing::point_at;
Vec3 blossom(const Poly& P, double x1, double x2, double x3) {
  const double xs[3] = {x1, x2, x3};
  std::array<Vec3, 4> d = P;
  for (int r = 0; r < 3; ++r)
    for (int i = 0; i + 1 < 4 - r; ++i) d[i] = (1 - xs[r]) * d[i] + xs[r] * d[i + 1];
  return d[0];
}
const Poly kP = {Vec3(0.1, 0.15, 0), Vec3(0.3, 0.9, 0), Vec3(0.75, 0.05, 0), Vec3(0.9, 0.8, 0)};

// Split at a parameter on a leaf boundary (any dyadic t = k/2^levels for uniform) must give the
// Euclidean de Casteljau halves on a plane; right[1] collapses onto P_t instead.
TEST(SurfaceRegressions, SplitAtALeafBoundary) {
  const TriMesh mesh = testing::build(testing::planar_grid(16));
  GeodesicSolver solver(mesh);
  CurveTracer tracer(solver);
  const ControlPolygon c = {point_at(mesh, kP[0]), point_at(mesh, kP[1]), point_at(mesh, kP[2]), point_at(mesh, kP[3])};
  for (Scheme scheme : {Scheme::kRDC, Scheme::kOLR})
    for (bool adaptive : {false, true})
      for (double t : {0.25, 0.375, 0.5}) {
        TraceOptions o;
        o.scheme = scheme;
        o.adaptive = adaptive;
        ControlPolygon left, right;
        tracer.split(c, t, o, left, right);
        EXPECT_NEAR((eval_position(mesh, right[1]) - blossom(kP, t, t, 1)).norm(), 0, 1e-7)
            << (scheme == Scheme::kRDC ? "RDC" : "OLR") << (adaptive ? " adaptive" : " uniform") << " t=" << t;
      }
}

// OLR adaptive on a plane: the subdivided polygon must not turn back on itself (5° bound).
TEST(SurfaceRegressions, OlrAdaptivePolygonDoesNotBacktrack) {
  const TriMesh mesh = testing::build(testing::planar_grid(16));
  GeodesicSolver solver(mesh);
  CurveTracer tracer(solver);
  const ControlPolygon c = {point_at(mesh, kP[0]), point_at(mesh, kP[1]), point_at(mesh, kP[2]), point_at(mesh, kP[3])};
  TraceOptions o;
  o.scheme = Scheme::kOLR;
  o.adaptive = true;
  std::vector<MeshPoint> pts;
  tracer.subdivide(c, o, pts);
  for (size_t i = 1; i + 1 < pts.size(); ++i) {
    const Vec3 a = eval_position(mesh, pts[i]) - eval_position(mesh, pts[i - 1]);
    const Vec3 b = eval_position(mesh, pts[i + 1]) - eval_position(mesh, pts[i]);
    EXPECT_LE(std::atan2(a.cross(b).norm(), a.dot(b)), o.angle + 1e-9)
        << "point " << i << " of " << pts.size() << " at " << eval_position(mesh, pts[i]).head<2>().transpose();
  }
}
}  // namespace
}  // namespace splinekit::surface
