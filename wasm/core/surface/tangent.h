// Tangent vectors on a mesh, straightest geodesics and parallel transport (b/Surf §5.1 "Straightest
// geodesics and parallel transport").
//   - Straightest geodesics follow Polthier & Schmies, "Straightest geodesics on polyhedral surfaces"
//     (1998): straight across faces and edges (unfolding); through a vertex of angle sum θ they leave
//     with θ/2 on either side; they stop at a boundary.
//   - Parallel transport along a path unfolds its strip into the plane and carries the vector along
//     unchanged (the discrete Levi-Civita connection of the strip).
//   - Polar angles at a point: in its face's frame (x along the face's first edge); at a vertex, the
//     angle around the vertex rescaled by 2π/θ, so normal coordinates cover a full turn.
#pragma once

#include "surface/geodesic.h"

#include <vector>

namespace splinekit::surface {

// The tangent `t` (at point p) expressed in the plane of face g, which must contain p.
Tangent tangent_in_face(const TriMesh& mesh, const MeshPoint& p, const Tangent& t, int g);

// Polar angle of a tangent at p, in [0, 2π) (see above), and the unit tangent of a polar angle (on a
// face whose corner sector contains it, for a vertex).
double polar_angle(const TriMesh& mesh, const MeshPoint& p, const Tangent& t);
Tangent polar_tangent(const TriMesh& mesh, const MeshPoint& p, double angle);

// Angle between a path arriving at p with direction `in` and one leaving with `out`, measured in the
// tangent plane (0 for a straight continuation; at a vertex of angle sum θ, |left angle − θ/2|).
double turning_angle(const TriMesh& mesh, const MeshPoint& p, const Tangent& in, const Tangent& out);

struct StraightestGeodesic {
  std::vector<MeshPoint> points;  // start, every crossing (and vertex), end; consecutive ones share a face
  MeshPoint end;
  Tangent end_direction;  // direction of travel at the end
  double length = 0;      // length traced (shorter than asked when it met a boundary)
  bool hit_boundary = false;
};

// Traces from p in direction `dir` (a tangent at p) for `length`.
void straightest_geodesic(const TriMesh& mesh, const MeshPoint& p, const Tangent& dir, double length,
                          StraightestGeodesic& out);

// The vector `v` (a tangent at path.start) carried along the path to path.end.
Tangent parallel_transport(const TriMesh& mesh, const GeodesicPath& path, const Tangent& v);

}  // namespace splinekit::surface
