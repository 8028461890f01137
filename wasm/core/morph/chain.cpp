#include "chain.h"

#include <algorithm>
#include <cmath>

#include "common/bezier.h"
#include "common/geometry.h"

namespace splinekit::morph {

int KnotChain::point_index(int k, int c) const {
  const int n = segments();
  const int p = 3 * k + c;
  return closed && p >= 3 * n ? p - 3 * n : p;
}

namespace {

Vec2 at(const std::vector<double>& p, int i) { return {p[2 * size_t(i)], p[2 * size_t(i) + 1]}; }

double segment_length(const KnotChain& c, int k) {
  double seg[8];
  for (int i = 0; i < 4; ++i) {
    const int p = c.point_index(k, i);
    seg[2 * i] = c.points[2 * size_t(p)];
    seg[2 * i + 1] = c.points[2 * size_t(p) + 1];
  }
  return bezier_arc_length(seg, 0.0, 1.0, 1e-9);
}

// Whether the anchor (point index p) with handles h_in, h_out is a C1-able join: both handles
// longer than tol and the anchor within tol of the segment h_in–h_out (collinear, same side).
bool collinear_join(const Vec2& h_in, const Vec2& p, const Vec2& h_out, double tol, double* ratio) {
  const Vec2 a = p - h_in, b = h_out - p;
  const double la = a.norm(), lb = b.norm();
  if (la <= tol || lb <= tol) return false;
  if (a.dot(b) <= 0) return false;
  const double dist = std::abs(cross(h_out - h_in, p - h_in)) / (h_out - h_in).norm();
  if (dist > tol) return false;
  *ratio = lb / la;
  return true;
}

}  // namespace

std::string chain_from_bezier(const double* points, int point_count, bool closed, const ChainOptions& options,
                              KnotChain& out) {
  const int n = spline_segment_count(point_count, closed);
  if (n < 1 || (closed ? point_count != 3 * n : point_count != 3 * n + 1)) {
    return "a contour needs at least one cubic segment (" + std::to_string(point_count) + " control points)";
  }
  for (int i = 0; i < 2 * point_count; ++i) {
    if (!std::isfinite(points[i])) return "a contour has a non-finite coordinate";
  }
  KnotChain c;
  c.closed = closed;
  c.points.assign(points, points + 2 * size_t(point_count));
  c.knots.assign(size_t(n), 0.0);
  c.smooth.assign(size_t(closed ? n : n + 1), 0);
  std::vector<double> ratio(c.smooth.size(), 1.0);
  std::vector<double> length(static_cast<size_t>(n));
  double total = 0;
  for (int k = 0; k < n; ++k) total += length[size_t(k)] = segment_length(c, k);
  if (!(total > 0)) return "a contour has zero length (all its points coincide)";
  for (int a = 0; a < c.anchors(); ++a) {
    if (!closed && (a == 0 || a == n)) continue;
    const int p = 3 * a;
    const int in = closed ? (p + 3 * n - 1) % (3 * n) : p - 1;
    double r = 1;
    if (collinear_join(at(c.points, in), at(c.points, p), at(c.points, p + 1), options.length_tolerance, &r)) {
      c.smooth[size_t(a)] = 1;
      ratio[size_t(a)] = r;
    }
  }
  // A closed chain starts at a C0 anchor when it has one: then every double knot's ratio is met.
  int first = 0;
  if (closed) {
    for (int a = 0; a < n; ++a) {
      if (!c.smooth[size_t(a)]) {
        first = a;
        break;
      }
    }
  }
  // Intervals: arc length at a C0 join (or the start), the handle ratio across a C1 join.
  for (int i = 0; i < n; ++i) {
    const int k = (first + i) % n;
    const int prev = (k + n - 1) % n;
    if (i > 0 && c.smooth[size_t(k)]) {
      c.knots[size_t(k)] = c.knots[size_t(prev)] * ratio[size_t(k)];
    } else {
      c.knots[size_t(k)] = std::max(length[size_t(k)], 1e-12 * total);
    }
  }
  if (closed && c.smooth[size_t(first)]) {
    // Every join is smooth: the closing one keeps its double knot only if the ratios close up.
    const int last = (first + n - 1) % n;
    const double want = c.knots[size_t(last)] * ratio[size_t(first)];
    if (std::abs(want - c.knots[size_t(first)]) > 1e-6 * c.knots[size_t(first)]) c.smooth[size_t(first)] = 0;
  }
  double sum = 0;
  for (double d : c.knots) sum += d;
  for (double& d : c.knots) d /= sum;
  out = first == 0 ? std::move(c) : rotated(c, first);
  if (options.max_length > 0) limit_segment_length(out, options.max_length);
  return "";
}

void limit_segment_length(KnotChain& chain, double max_length) {
  const int n = chain.segments();
  KnotChain out;
  out.closed = chain.closed;
  double seg[8], left[8], right[8];
  for (int k = 0; k < n; ++k) {
    for (int i = 0; i < 4; ++i) {
      const int p = chain.point_index(k, i);
      seg[2 * i] = chain.points[2 * size_t(p)];
      seg[2 * i + 1] = chain.points[2 * size_t(p) + 1];
    }
    const double length = bezier_arc_length(seg, 0.0, 1.0, 1e-9);
    const int pieces = std::max(1, int(std::ceil(length / max_length - 1e-9)));
    for (int piece = 0; piece < pieces; ++piece) {
      out.smooth.push_back(piece == 0 ? chain.smooth[size_t(k)] : 1);
      out.knots.push_back(chain.knots[size_t(k)] / pieces);
      if (piece + 1 < pieces) {
        // Split off 1/(pieces - piece) of what is left: equal parameter steps of the original.
        bezier_split(seg, 1.0 / double(pieces - piece), left, right);
        out.points.insert(out.points.end(), left, left + 6);
        std::copy(right, right + 8, seg);
      } else {
        out.points.insert(out.points.end(), seg, seg + 6);
      }
    }
  }
  if (!chain.closed) {
    out.points.push_back(chain.points[chain.points.size() - 2]);
    out.points.push_back(chain.points.back());
    out.smooth.push_back(chain.smooth.back());
  }
  chain = std::move(out);
}

KnotChain reversed(const KnotChain& chain) {
  KnotChain out;
  out.closed = chain.closed;
  const int n = chain.segments();
  const int count = int(chain.points.size() / 2);
  out.points.resize(chain.points.size());
  for (int i = 0; i < count; ++i) {
    // Closed: point i goes to (3n - i) mod 3n, so anchor 0 stays anchor 0; open: to count-1-i.
    const int j = chain.closed ? (3 * n - i) % (3 * n) : count - 1 - i;
    out.points[2 * size_t(j)] = chain.points[2 * size_t(i)];
    out.points[2 * size_t(j) + 1] = chain.points[2 * size_t(i) + 1];
  }
  out.knots.resize(size_t(n));
  for (int k = 0; k < n; ++k) out.knots[size_t(n - 1 - k)] = chain.knots[size_t(k)];
  out.smooth.resize(chain.smooth.size());
  const int a = chain.anchors();
  for (int i = 0; i < a; ++i) out.smooth[size_t(chain.closed ? (a - i) % a : a - 1 - i)] = chain.smooth[size_t(i)];
  return out;
}

KnotChain rotated(const KnotChain& chain, int first) {
  if (!chain.closed || chain.segments() == 0) return chain;
  const int n = chain.segments();
  first = ((first % n) + n) % n;
  KnotChain out;
  out.closed = true;
  out.points.resize(chain.points.size());
  for (int i = 0; i < 3 * n; ++i) {
    const int from = (i + 3 * first) % (3 * n);
    out.points[2 * size_t(i)] = chain.points[2 * size_t(from)];
    out.points[2 * size_t(i) + 1] = chain.points[2 * size_t(from) + 1];
  }
  out.knots.resize(size_t(n));
  out.smooth.resize(size_t(n));
  for (int k = 0; k < n; ++k) {
    out.knots[size_t(k)] = chain.knots[size_t((k + first) % n)];
    out.smooth[size_t(k)] = chain.smooth[size_t((k + first) % n)];
  }
  return out;
}

KnotChain point_chain(double x, double y, int segments, bool closed) {
  KnotChain c;
  c.closed = closed;
  const int count = closed ? 3 * segments : 3 * segments + 1;
  c.points.resize(2 * size_t(count));
  for (int i = 0; i < count; ++i) {
    c.points[2 * size_t(i)] = x;
    c.points[2 * size_t(i) + 1] = y;
  }
  c.knots.assign(size_t(segments), 0.0);
  c.smooth.assign(size_t(closed ? segments : segments + 1), 0);
  return c;
}

}  // namespace splinekit::morph
