// splinekit — which contour of one key blends into which of the other (beyond the paper, which
// blends one closed B-spline into one).
//
// Each contour is described by its signed area, centroid and nesting depth (how many other
// contours of its drawing enclose it), positions and areas measured relative to its drawing's
// bounding box so that keys of different size and place still pair up. Contours pair by least
// total cost (exhaustively for up to 7 contours on the smaller side, greedily beyond): a hole
// pairs with a hole, an open path only with an open path. A contour left without a partner
// grows from (or shrinks to) a point inside its own region, carried into the other key by the
// box of its parent's partner (else of the whole drawing) — never from the origin.
#pragma once

#include <string>
#include <vector>

#include "common/geometry.h"
#include "common/spline_set.h"

namespace splinekit::morph {

struct ContourShape {
  bool closed = false;
  double area = 0;  // signed (positive counter-clockwise in a y-up frame)
  Vec2 centroid = Vec2::Zero();
  Vec2 inside = Vec2::Zero();    // a point inside the region (midpoint of its widest horizontal chord)
  double box[4] = {0, 0, 0, 0};  // xmin, ymin, xmax, ymax
  int depth = 0;                 // contours of the same drawing that enclose it
  int parent = -1;               // the innermost enclosing contour, or -1
  std::vector<double> outline;   // the contour sampled as a polygon (x, y pairs)
};

// Describes every spline of a set (sampled at `samples` points per segment).
std::vector<ContourShape> describe_contours(const SplineSet& set, int samples = 16);

// Cost of blending contour a (of a drawing with box box_a) into contour b (box_b); +inf when they
// cannot pair (open with closed).
double pairing_cost(const ContourShape& a, const double* box_a, const ContourShape& b, const double* box_b);

// partner_of_a[i] = the contour of B that A's contour i blends into, or -1 (shrinks to a point);
// same for partner_of_b. `bonus[i * nb + j]` is subtracted from the cost of pairing i with j
// (pins pull their contours together).
void pair_contours(const std::vector<ContourShape>& a, const double* box_a, const std::vector<ContourShape>& b,
                   const double* box_b, const std::vector<double>& bonus, std::vector<int>& partner_of_a,
                   std::vector<int>& partner_of_b);

// Where a contour without partner grows from / shrinks to in the other drawing: its own inside
// point mapped from its parent's box to the parent's partner's box (or drawing box to drawing box),
// then moved to the nearest middle of a horizontal chord through the filled region of the parent's
// partner (inside it, outside its holes), so that it starts or ends inside the partner's region.
Vec2 partner_point(const ContourShape& c, const std::vector<ContourShape>& own, const double* own_box,
                   const std::vector<ContourShape>& other, const double* other_box,
                   const std::vector<int>& partner_of_own);

}  // namespace splinekit::morph
