// Editing splines on a mesh with the gestures of a 2D editor (b/Surf §5.2), and mapping 2D drawings
// onto the mesh. A spline is its control points: anchors at 3k, handles at 3k±1 (3n+1 points).
//   - Moving an anchor carries its handles along: each handle's direction at the old anchor is
//     parallel-transported to the new one and a straightest geodesic of the same length is traced.
//   - Moving a handle at a smooth anchor makes the opposite handle follow along the straightest
//     geodesic through the anchor, keeping its length.
//   - Translation, rotation and scaling work in normal (polar) coordinates about a mesh point C;
//     translation from C to C' rotates the coordinates by the transport of C's frame to C'.
//   - A 2D drawing maps through polar coordinates about a centre, traced as straightest geodesics.
#pragma once

#include "surface/geodesic.h"
#include "surface/tangent.h"

#include <vector>

namespace splinekit::surface {

struct Polar {
  double radius = 0;
  double angle = 0;  // polar angle at the centre (tangent.h)
};

// Normal coordinates of x about c (the shortest path's length and initial direction), and back.
Polar log_map(GeodesicSolver& solver, const MeshPoint& c, const MeshPoint& x);
MeshPoint exp_map(const TriMesh& mesh, const MeshPoint& c, const Polar& polar);

void move_anchor(GeodesicSolver& solver, std::vector<MeshPoint>& points, int anchor, const MeshPoint& to);
void move_handle(GeodesicSolver& solver, std::vector<MeshPoint>& points, int handle, const MeshPoint& to, bool smooth);
// Makes the anchor smooth: the handle after it is put opposite the one before it (same length as it had).
void make_smooth(GeodesicSolver& solver, std::vector<MeshPoint>& points, int anchor);

// Rotation by `angle` and scaling by `scale` about c.
void rotate_scale(GeodesicSolver& solver, std::vector<MeshPoint>& points, const MeshPoint& c, double angle,
                  double scale);
// Translation that takes `from` to `to`.
void translate(GeodesicSolver& solver, std::vector<MeshPoint>& points, const MeshPoint& from, const MeshPoint& to);

// Maps 2D points (x right, y down, as in SVG) about `center`: `up` (a 3D direction, projected to the
// tangent plane; zero for the face's own frame) is where the drawing's up (-y) goes, then `rotation`
// (radians, counter-clockwise seen from outside) and `scale` (mesh units per drawing unit).
void map_points(const TriMesh& mesh, const MeshPoint& center, const Vec3& up, double rotation, double scale,
                const double* xy, int count, std::vector<MeshPoint>& out);

}  // namespace splinekit::surface
