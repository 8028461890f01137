// Phase (ii) of a locally shortest path (b/Surf §5.1): the shortest path inside a strip of faces
// laid flat in the plane, by the funnel algorithm (Lee & Preparata 1984, "Euclidean shortest paths
// in the presence of rectilinear barriers"; here its "simple stupid funnel" form), and what phase
// (iii) reads off that path: its bends (apices), their turning angles, and its edge crossings.
#pragma once

#include "surface/unfold.h"

#include <cmath>
#include <vector>

namespace splinekit::surface {

// A bend of the funnel's path (or one of its ends).
struct Apex {
  Vec2 pos;
  int vertex = -1;   // mesh vertex (-1 for the end points)
  int portal = -1;   // index of the last portal it bounds (-1 for the start; #portals for the end)
  int emitted = -1;  // the portal whose processing made it the apex (the funnel's state from then on
                     // depends on it and the portals after it only)
};

// How a strip differs from one whose funnel path is known (`path`): its portals before `lo` are
// that strip's, and its portals from `hi` on are that strip's portals `shift` further on, moved by
// `motion`. Where it differs in several places (a pass's flips), `between` lists the stretches
// between them, in strip order: portals [from, to) are the known strip's `shift` further on, moved
// by `motion`.
struct Splice {
  struct Agreement {
    int from = 0, to = 0, shift = 0;
    PlaneMotion motion;
  };
  const std::vector<Apex>* path = nullptr;
  int lo = 0, hi = 0, shift = 0;
  PlaneMotion motion;
  std::vector<Agreement> between;
};

// The shortest path from `source` (on u's first face) to `target` (on its last) inside the
// unfolded strip u, as its apices: source, the bends (mesh vertices), target.
// With a splice, the funnel takes up the known path at its last apex made before `lo` (from there
// on it is in the same state), and once an apex beyond `hi` is one of the known path's, it ends
// with that path's (the same portals follow, moved). Likewise in each stretch `between`: once an
// apex there is one of the known path's, the known apices the stretch's portals make follow, and
// the funnel goes on from the last of them. So its work follows the changes, not the strip.
void funnel(const UnfoldedStrip& u, const Vec2& source, const Vec2& target, std::vector<Apex>& apices,
            const Splice* splice = nullptr);

// Turning angle of the path at apex j in radians, in [0, π] (0 at the ends).
inline double turn_at(const std::vector<Apex>& apices, size_t j) {
  if (j == 0 || j + 1 >= apices.size()) return 0;
  const Vec2 a = apices[j].pos - apices[j - 1].pos, b = apices[j + 1].pos - apices[j].pos;
  return std::atan2(std::abs(cross(a, b)), a.dot(b));
}

// Drops the apices where the funnel's path goes straight on but for rounding (a vertex on the line
// between its neighbours): they would stand in for the real bends next to them.
void drop_straight(std::vector<Apex>& apices);

// Lerps on every portal (#portals) from the funnel's polyline, and the arc length at each point of
// the path (#portals+2: start, crossings, end).
void crossings(const UnfoldedStrip& u, const std::vector<Apex>& apices, std::vector<double>& lerps,
               std::vector<double>& arc);

// Length of the polyline through the apices.
inline double polyline_length(const std::vector<Apex>& apices) {
  double length = 0;
  for (size_t j = 1; j < apices.size(); ++j) length += (apices[j].pos - apices[j - 1].pos).norm();
  return length;
}

}  // namespace splinekit::surface
