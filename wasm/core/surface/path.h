// Geodesic paths on a triangle mesh as b/Surf stores them (§5.1): the strip of faces a path crosses
// and where it crosses the edges between them, with the queries curve tracing asks of a path
// (points, length, the point at an arc-length fraction, sub-paths, end tangents).
#pragma once

#include "surface/mesh.h"

#include <vector>

namespace splinekit::surface {

// A path is its strip of faces and the intercepts (lerps) on the edges between consecutive faces.
struct GeodesicPath {
  MeshPoint start, end;       // start on strip.front(), end on strip.back()
  std::vector<int> strip;     // faces crossed, consecutive ones adjacent
  std::vector<double> lerps;  // #strip-1: crossing of edge (t[k], t[k+1]) of strip[i] toward strip[i+1]
  // Arc length at the start, each crossing and the end (#strip+1), as the straightening measured it
  // in the unfolded strip; empty when not known (then measured when needed).
  std::vector<double> arc;
};

// ---- Points and length --------------------------------------------------------------------------

// Start, every edge crossing, end (#strip+1 mesh points; crossing i expressed on strip[i]).
void path_points(const TriMesh& mesh, const GeodesicPath& path, std::vector<MeshPoint>& points);
// The same points in space (#strip+1 positions).
void path_positions(const TriMesh& mesh, const GeodesicPath& path, std::vector<Vec3>& positions);
// Length in space, summed over the segments between consecutive points.
double path_length(const TriMesh& mesh, const GeodesicPath& path);

// ---- Parts ----------------------------------------------------------------------------------------

// The point at arc-length fraction t in [0, 1].
MeshPoint eval_path(const TriMesh& mesh, const GeodesicPath& path, double t);
// The part of the path between fractions t0 <= t1 (a path again: strip and lerps).
GeodesicPath sub_path(const TriMesh& mesh, const GeodesicPath& path, double t0, double t1);
// The same path run from end to start.
GeodesicPath reversed(const TriMesh& mesh, const GeodesicPath& path);

// ---- Tangents -------------------------------------------------------------------------------------

// A tangent vector at a point: a 3D vector in the plane of `face`, which contains the point.
struct Tangent {
  int face = -1;
  Vec3 dir = Vec3::Zero();
};
// Unit direction in which the path leaves its start / arrives at its end (zero dir for a point path).
Tangent start_tangent(const TriMesh& mesh, const GeodesicPath& path);
Tangent end_tangent(const TriMesh& mesh, const GeodesicPath& path);

// ---- Strips ---------------------------------------------------------------------------------------

// Cuts the loops out of a strip: when a face appears twice, the faces between are dropped.
// face_marks: #F (or more) entries, -1 everywhere on entry and again on return.
void remove_loops(std::vector<int>& strip, std::vector<int>& face_marks);
// The faces around `faces` (theirs included, no face twice) into `out`: breadth first across edges,
// each face reached from one of `faces` whose centroid lies within `width` (in space) of that
// face's. face_marks as for remove_loops.
void grow_faces(const TriMesh& mesh, const std::vector<int>& faces, double width, std::vector<int>& face_marks,
                std::vector<int>& out);

}  // namespace splinekit::surface
