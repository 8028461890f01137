#include "pairing.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "common/bezier.h"

namespace splinekit::morph {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Winding number of polygon `poly` (x,y pairs, closed implicitly) around p.
int winding(const std::vector<double>& poly, const Vec2& p) {
  int w = 0;
  const size_t n = poly.size() / 2;
  for (size_t i = 0; i < n; ++i) {
    const Vec2 a(poly[2 * i], poly[2 * i + 1]);
    const Vec2 b(poly[2 * ((i + 1) % n)], poly[2 * ((i + 1) % n) + 1]);
    if (a.y() <= p.y()) {
      if (b.y() > p.y() && orient(a, b, p) > 0) ++w;
    } else if (b.y() <= p.y() && orient(a, b, p) < 0) {
      --w;
    }
  }
  return w;
}

}  // namespace

std::vector<ContourShape> describe_contours(const SplineSet& set, int samples) {
  const int count = set.spline_count();
  std::vector<ContourShape> out(static_cast<size_t>(count));
  std::vector<std::vector<double>> polys(static_cast<size_t>(count));
  for (int s = 0; s < count; ++s) {
    ContourShape& c = out[size_t(s)];
    c.closed = set.closed[size_t(s)] != 0;
    const int n = spline_segment_count(set.count[size_t(s)], c.closed);
    std::vector<double>& poly = polys[size_t(s)];
    double seg[8];
    for (int k = 0; k < n; ++k) {
      spline_segment(set.spline_points(s), set.count[size_t(s)], c.closed, k, seg);
      for (int i = 0; i < samples; ++i) {
        const Vec2 p = bezier_point(seg, double(i) / samples);
        poly.push_back(p.x());
        poly.push_back(p.y());
      }
    }
    spline_bounds(set.spline_points(s), set.count[size_t(s)], c.closed, c.box);
    const size_t m = poly.size() / 2;
    double a2 = 0, cx = 0, cy = 0, len = 0;
    for (size_t i = 0; i < m; ++i) {
      const size_t j = (i + 1) % m;
      const double x0 = poly[2 * i], y0 = poly[2 * i + 1], x1 = poly[2 * j], y1 = poly[2 * j + 1];
      const double cr = x0 * y1 - x1 * y0;
      a2 += cr;
      cx += (x0 + x1) * cr;
      cy += (y0 + y1) * cr;
      len += std::hypot(x1 - x0, y1 - y0);
    }
    c.area = c.closed ? a2 / 2 : 0.0;
    if (c.closed && std::abs(a2) > 1e-12 * len * len) {
      c.centroid = Vec2(cx / (3 * a2), cy / (3 * a2));
    } else {
      double sx = 0, sy = 0;
      for (size_t i = 0; i < m; ++i) sx += poly[2 * i], sy += poly[2 * i + 1];
      c.centroid = Vec2(sx / double(std::max<size_t>(m, 1)), sy / double(std::max<size_t>(m, 1)));
    }
    // Inside point: the midpoint of the widest interval inside the polygon on the line y = centroid.
    c.inside = c.centroid;
    if (c.closed && m >= 3) {
      const double y = c.centroid.y();
      std::vector<double> xs;
      for (size_t i = 0; i < m; ++i) {
        const size_t j = (i + 1) % m;
        const double y0 = poly[2 * i + 1], y1 = poly[2 * j + 1];
        if ((y0 <= y) != (y1 <= y)) xs.push_back(poly[2 * i] + (y - y0) / (y1 - y0) * (poly[2 * j] - poly[2 * i]));
      }
      std::sort(xs.begin(), xs.end());
      double widest = -1;
      for (size_t i = 0; i + 1 < xs.size(); i += 2) {
        if (xs[i + 1] - xs[i] > widest) {
          widest = xs[i + 1] - xs[i];
          c.inside = Vec2((xs[i] + xs[i + 1]) / 2, y);
        }
      }
    }
  }
  for (int s = 0; s < count; ++s) out[size_t(s)].outline = polys[size_t(s)];
  // Nesting: a contour's first point inside another closed contour's polygon.
  for (int s = 0; s < count; ++s) {
    const Vec2 p = vec2_at(set.spline_points(s));
    double smallest = kInf;
    for (int o = 0; o < count; ++o) {
      if (o == s || !out[size_t(o)].closed) continue;
      const double* b = out[size_t(o)].box;
      if (p.x() < b[0] || p.x() > b[2] || p.y() < b[1] || p.y() > b[3]) continue;  // cheap reject
      if (winding(polys[size_t(o)], p) != 0) {
        ++out[size_t(s)].depth;
        if (std::abs(out[size_t(o)].area) < smallest) {
          smallest = std::abs(out[size_t(o)].area);
          out[size_t(s)].parent = o;
        }
      }
    }
  }
  return out;
}

double pairing_cost(const ContourShape& a, const double* box_a, const ContourShape& b, const double* box_b) {
  if (a.closed != b.closed) return kInf;
  const double wa = std::max(box_a[2] - box_a[0], 1e-300), ha = std::max(box_a[3] - box_a[1], 1e-300);
  const double wb = std::max(box_b[2] - box_b[0], 1e-300), hb = std::max(box_b[3] - box_b[1], 1e-300);
  const Vec2 ca((a.centroid.x() - box_a[0]) / wa, (a.centroid.y() - box_a[1]) / ha);
  const Vec2 cb((b.centroid.x() - box_b[0]) / wb, (b.centroid.y() - box_b[1]) / hb);
  const double sa = std::sqrt(std::abs(a.area) / (wa * ha)), sb = std::sqrt(std::abs(b.area) / (wb * hb));
  const double nesting = (a.depth % 2) != (b.depth % 2) ? 2.0 : 0.0;
  return (ca - cb).norm() + std::abs(sa - sb) + nesting;
}

void pair_contours(const std::vector<ContourShape>& a, const double* box_a, const std::vector<ContourShape>& b,
                   const double* box_b, const std::vector<double>& bonus, std::vector<int>& partner_of_a,
                   std::vector<int>& partner_of_b) {
  const int na = int(a.size()), nb = int(b.size());
  std::vector<double> cost(size_t(na) * nb);
  for (int i = 0; i < na; ++i)
    for (int j = 0; j < nb; ++j)
      cost[size_t(i) * nb + j] =
          pairing_cost(a[size_t(i)], box_a, b[size_t(j)], box_b) - (bonus.empty() ? 0.0 : bonus[size_t(i) * nb + j]);
  partner_of_a.assign(size_t(na), -1);
  partner_of_b.assign(size_t(nb), -1);
  const bool a_smaller = na <= nb;
  const int small = a_smaller ? na : nb, large = a_smaller ? nb : na;
  auto c = [&](int s, int l) { return a_smaller ? cost[size_t(s) * nb + l] : cost[size_t(l) * nb + s]; };
  std::vector<int> best(size_t(small), -1);
  if (small == 0) return;
  if (small <= 7 && large <= 9) {
    // Every injective map small → large (large ≤ 9: at most 9!/2! maps).
    std::vector<int> perm(static_cast<size_t>(large));
    std::iota(perm.begin(), perm.end(), 0);
    double best_cost = kInf;
    int best_pairs = -1;
    do {
      double total = 0;
      int pairs = 0;
      for (int s = 0; s < small; ++s) {
        const double v = c(s, perm[size_t(s)]);
        if (std::isfinite(v)) total += v, ++pairs;
      }
      if (pairs > best_pairs || (pairs == best_pairs && total < best_cost - 1e-12)) {
        best_pairs = pairs;
        best_cost = total;
        for (int s = 0; s < small; ++s) best[size_t(s)] = std::isfinite(c(s, perm[size_t(s)])) ? perm[size_t(s)] : -1;
      }
      // Only the first `small` entries matter: skip the permutations of the rest.
      std::reverse(perm.begin() + small, perm.end());
    } while (std::next_permutation(perm.begin(), perm.end()));
  } else {
    // Greedy: the cheapest remaining pair first (all pairs sorted once, O(n² log n)).
    std::vector<std::pair<double, int64_t>> order;
    order.reserve(size_t(small) * size_t(large));
    for (int s = 0; s < small; ++s)
      for (int l = 0; l < large; ++l)
        if (std::isfinite(c(s, l))) order.push_back({c(s, l), int64_t(s) * large + l});
    std::sort(order.begin(), order.end());
    std::vector<uint8_t> used(size_t(large), 0);
    for (const auto& [cost_sl, sl] : order) {
      const int s = int(sl / large), l = int(sl % large);
      if (best[size_t(s)] >= 0 || used[size_t(l)]) continue;
      best[size_t(s)] = l;
      used[size_t(l)] = 1;
    }
  }
  for (int s = 0; s < small; ++s) {
    if (best[size_t(s)] < 0) continue;
    if (a_smaller) {
      partner_of_a[size_t(s)] = best[size_t(s)];
      partner_of_b[size_t(best[size_t(s)])] = s;
    } else {
      partner_of_b[size_t(s)] = best[size_t(s)];
      partner_of_a[size_t(best[size_t(s)])] = s;
    }
  }
}

Vec2 partner_point(const ContourShape& c, const std::vector<ContourShape>& own, const double* own_box,
                   const std::vector<ContourShape>& other, const double* other_box,
                   const std::vector<int>& partner_of_own) {
  const double* from = own_box;
  const double* to = other_box;
  if (c.parent >= 0 && partner_of_own[size_t(c.parent)] >= 0) {
    from = own[size_t(c.parent)].box;
    to = other[size_t(partner_of_own[size_t(c.parent)])].box;
  }
  const double fw = from[2] - from[0], fh = from[3] - from[1];
  const double u = fw > 0 ? (c.inside.x() - from[0]) / fw : 0.5, v = fh > 0 ? (c.inside.y() - from[1]) / fh : 0.5;
  const Vec2 mapped(to[0] + u * (to[2] - to[0]), to[1] + v * (to[3] - to[1]));
  if (c.parent < 0 || partner_of_own[size_t(c.parent)] < 0) return mapped;
  // The filled region: the parent's partner minus the contours directly inside it.
  const int region = partner_of_own[size_t(c.parent)];
  std::vector<const std::vector<double>*> rings = {&other[size_t(region)].outline};
  for (const ContourShape& o : other)
    if (o.parent == region) rings.push_back(&o.outline);
  Vec2 best = mapped;
  double best_d = std::numeric_limits<double>::infinity();
  const double* box = other[size_t(region)].box;
  std::vector<double> xs;
  for (int row = 1; row < 64; ++row) {
    const double y = box[1] + (box[3] - box[1]) * row / 64.0;
    xs.clear();
    for (const std::vector<double>* r : rings) {
      const size_t m = r->size() / 2;
      for (size_t i = 0; i < m; ++i) {
        const size_t j = (i + 1) % m;
        const double y0 = (*r)[2 * i + 1], y1 = (*r)[2 * j + 1];
        if ((y0 <= y) != (y1 <= y)) xs.push_back((*r)[2 * i] + (y - y0) / (y1 - y0) * ((*r)[2 * j] - (*r)[2 * i]));
      }
    }
    std::sort(xs.begin(), xs.end());
    for (size_t i = 0; i + 1 < xs.size(); i += 2) {
      const Vec2 mid((xs[i] + xs[i + 1]) / 2, y);
      const double d = (mid - mapped).norm();
      if (d < best_d) best_d = d, best = mid;
    }
  }
  return best;
}

}  // namespace splinekit::morph
