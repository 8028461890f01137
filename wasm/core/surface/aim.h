// Between phases (ii) and (iii) of a locally shortest path from the dual graph: the end-to-end
// chord of the strip, re-aimed by the secant method (a shooting method for the two-point problem,
// with straight walks across faces as in b/Surf §5.1 "Straightest geodesics").
//
// A strip found on the dual graph lies rows of vertices away from the geodesic on long paths (its
// faces hop from centroid to centroid, and on a grid many staircases are equally short), and
// phase (iii)'s flips move the path across one row per pass. A straight line from the start point,
// aimed at where the strip's layout puts the end point and walked across the mesh face by face
// (each face laid flat next to the last, so the line is a geodesic wherever it meets no vertex),
// crosses the faces of a geodesic at once. It rarely reaches the end point's face on the first
// shot: the surface between turns it. So where it passes the end point instead, the walk stops
// and reads the miss off the face it passed it in (where that face's plane puts the end point:
// the sine of the angle at the start between the line and that point), and the line is aimed
// again: first at that point, then by the secant method on the angle (regula falsi, Illinois
// variant, once the misses change sign). It gives up after `shots` shots, when a walk meets a
// boundary or a vertex or grows past twice the strip, and when the miss has not halved in two
// shots (on noisy surfaces the miss jumps by every vertex the line passes: no shot count helps).
//
// The straightening keeps the aimed strip only where its funnel path is shorter than the dual
// strip's (straighten.h), as it keeps any flip.
#pragma once

#include "surface/unfold.h"

#include <vector>

namespace splinekit::surface {

// The faces a straight line from `start` (on u's first face) crosses to `end`'s face (u's last),
// into `faces` (from u's first face to end.face), aimed as above: true when a shot reached it.
// `fired`: the shots walked (added to).
bool aim(const TriMesh& mesh, const UnfoldedStrip& u, const MeshPoint& start, const MeshPoint& end, int shots,
         std::vector<int>& faces, int& fired);

}  // namespace splinekit::surface
