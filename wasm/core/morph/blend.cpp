#include "blend.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/geometry.h"

namespace splinekit::morph {

namespace {

void put(std::vector<double>& v, int p, const double* xy) {
  v[2 * size_t(p)] = xy[0];
  v[2 * size_t(p) + 1] = xy[1];
}

double wrap(double a) {
  while (a > kPi) a -= 2 * kPi;
  while (a <= -kPi) a += 2 * kPi;
  return a;
}

}  // namespace

void ContourBlend::build(const KnotChain& a, const KnotChain& b, const std::vector<Move>& moves) {
  closed_ = a.closed;
  segments_ = int(moves.size());
  const int count = point_count();
  a_.assign(2 * size_t(count), 0.0);
  b_.assign(2 * size_t(count), 0.0);
  da_.assign(size_t(segments_), 0.0);
  db_.assign(size_t(segments_), 0.0);
  const int anchors = closed_ ? segments_ : segments_ + 1;
  coupled_.assign(size_t(anchors), 0);
  corr_a_.assign(2 * size_t(anchors), 0.0);
  corr_b_.assign(2 * size_t(anchors), 0.0);
  std::vector<int> anchor_a(static_cast<size_t>(anchors)), anchor_b(static_cast<size_t>(anchors));
  int i = 0, j = 0;
  for (int k = 0; k < segments_; ++k) {
    anchor_a[size_t(k)] = a.closed ? i % a.anchors() : i;
    anchor_b[size_t(k)] = b.closed ? j % b.anchors() : j;
    const Move mv = moves[size_t(k)];
    for (int c = 0; c < 3; ++c) {
      const int pa = mv == Move::kSecond ? 3 * anchor_a[size_t(k)] : a.point_index(i, c);
      const int pb = mv == Move::kFirst ? 3 * anchor_b[size_t(k)] : b.point_index(j, c);
      put(a_, 3 * k + c, &a.points[2 * size_t(pa)]);
      put(b_, 3 * k + c, &b.points[2 * size_t(pb)]);
    }
    if (mv != Move::kSecond) da_[size_t(k)] = a.knots[size_t(i++)];
    if (mv != Move::kFirst) db_[size_t(k)] = b.knots[size_t(j++)];
  }
  if (!closed_) {
    anchor_a[size_t(segments_)] = a.anchors() - 1;
    anchor_b[size_t(segments_)] = b.anchors() - 1;
    put(a_, 3 * segments_, &a.points[a.points.size() - 2]);
    put(b_, 3 * segments_, &b.points[b.points.size() - 2]);
  }
  // Anchors on a double knot in both keys, with a real segment on either side in both.
  for (int k = 0; k < anchors; ++k) {
    if (!closed_ && (k == 0 || k == segments_)) continue;
    const int prev = (k + segments_ - 1) % segments_;
    if (da_[size_t(prev)] <= 0 || da_[size_t(k)] <= 0 || db_[size_t(prev)] <= 0 || db_[size_t(k)] <= 0) continue;
    if (!a.smooth[size_t(anchor_a[size_t(k)])] || !b.smooth[size_t(anchor_b[size_t(k)])]) continue;
    coupled_[size_t(k)] = 1;
  }
  // Each key's offset from its anchor formula (zero for exactly C1 joins).
  std::vector<double> key(2 * size_t(count));
  for (int which = 0; which < 2; ++which) {
    const std::vector<double>& src = which == 0 ? a_ : b_;
    std::vector<double>& corr = which == 0 ? corr_a_ : corr_b_;
    std::fill(corr.begin(), corr.end(), 0.0);
    key = src;
    anchors_from_knots(double(which), key.data());
    for (int k = 0; k < anchors; ++k) {
      if (!coupled_[size_t(k)]) continue;
      corr[2 * size_t(k)] = src[6 * size_t(k)] - key[6 * size_t(k)];
      corr[2 * size_t(k) + 1] = src[6 * size_t(k) + 1] - key[6 * size_t(k) + 1];
    }
  }
  prepare_intrinsic();
}

void ContourBlend::anchors_from_knots(double t, double* out) const {
  const int count = point_count();
  const int anchors = closed_ ? segments_ : segments_ + 1;
  for (int k = 0; k < anchors; ++k) {
    if (!coupled_[size_t(k)]) continue;
    const int prev = (k + segments_ - 1) % segments_;
    const double dl = (1 - t) * da_[size_t(prev)] + t * db_[size_t(prev)];
    const double dr = (1 - t) * da_[size_t(k)] + t * db_[size_t(k)];
    const int in = (3 * k - 1 + count) % count, o = 3 * k + 1;
    for (int c = 0; c < 2; ++c) {
      out[6 * size_t(k) + c] = (dr * out[2 * size_t(in) + c] + dl * out[2 * size_t(o) + c]) / (dl + dr) +
                               (1 - t) * corr_a_[2 * size_t(k) + c] + t * corr_b_[2 * size_t(k) + c];
    }
  }
}

void ContourBlend::linear(double t, double* out) const {
  const size_t n = a_.size();
  for (size_t i = 0; i < n; ++i) out[i] = (1 - t) * a_[i] + t * b_[i];
}

void ContourBlend::evaluate(double t, Interpolation mode, double* out) {
  if (mode == Interpolation::kIntrinsic && !collapsed_key_ && polygon_.size() >= 2) {
    intrinsic(t, out);
  } else {
    linear(t, out);
  }
  anchors_from_knots(t, out);
}

void ContourBlend::prepare_intrinsic() {
  const int count = point_count();
  polygon_.clear();
  for (int p = 0; p < count; ++p) {
    if (p % 3 == 0 && coupled_[size_t(p / 3)]) continue;
    polygon_.push_back(p);
  }
  const int v = int(polygon_.size());
  const int edges = closed_ ? v : v - 1;
  len_a_.assign(size_t(std::max(edges, 0)), 0.0);
  len_b_ = turn_a_ = turn_b_ = weight_ = len_a_;
  edges_.assign(2 * size_t(std::max(edges, 0)), 0.0);
  double extent = 0;
  for (size_t i = 0; i < a_.size(); ++i) extent = std::max({extent, std::abs(a_[i] - a_[0]), std::abs(b_[i] - b_[0])});
  collapsed_key_ = false;
  for (int which = 0; which < 2; ++which) {
    const std::vector<double>& src = which == 0 ? a_ : b_;
    std::vector<double>& len = which == 0 ? len_a_ : len_b_;
    std::vector<double>& turn = which == 0 ? turn_a_ : turn_b_;
    double* centroid = which == 0 ? centroid_a_ : centroid_b_;
    centroid[0] = centroid[1] = 0;
    for (int p : polygon_) {
      centroid[0] += src[2 * size_t(p)] / v;
      centroid[1] += src[2 * size_t(p) + 1] / v;
    }
    // Edge angles; a zero-length edge takes the direction of the edge before it (the first
    // non-zero one for leading zero edges).
    std::vector<double> angle(size_t(std::max(edges, 0)), 0.0);
    int first_nonzero = -1;
    for (int e = 0; e < edges; ++e) {
      const int p = polygon_[size_t(e)], q = polygon_[size_t((e + 1) % v)];
      const double dx = src[2 * size_t(q)] - src[2 * size_t(p)], dy = src[2 * size_t(q) + 1] - src[2 * size_t(p) + 1];
      len[size_t(e)] = std::hypot(dx, dy);
      if (len[size_t(e)] > 1e-12 * extent) {
        angle[size_t(e)] = std::atan2(dy, dx);
        if (first_nonzero < 0) first_nonzero = e;
      } else {
        angle[size_t(e)] = std::numeric_limits<double>::quiet_NaN();
      }
    }
    if (first_nonzero < 0) {
      collapsed_key_ = true;
      continue;
    }
    double last = angle[size_t(first_nonzero)];
    for (int e = 0; e < edges; ++e) {
      if (std::isnan(angle[size_t(e)])) angle[size_t(e)] = last;
      last = angle[size_t(e)];
    }
    (which == 0 ? angle_a_ : angle_b_) = angle[0];
    for (int e = 1; e < edges; ++e) turn[size_t(e)] = wrap(angle[size_t(e)] - angle[size_t(e - 1)]);
  }
  for (int e = 0; e < edges; ++e)
    weight_[size_t(e)] = std::max(std::abs(len_a_[size_t(e)] - len_b_[size_t(e)]), 1e-6 * extent);
}

void ContourBlend::intrinsic(double t, double* out) {
  const int v = int(polygon_.size());
  const int edges = closed_ ? v : v - 1;
  double angle = angle_a_ + t * wrap(angle_b_ - angle_a_);
  double gap_x = 0, gap_y = 0;
  for (int e = 0; e < edges; ++e) {
    if (e > 0) angle += (1 - t) * turn_a_[size_t(e)] + t * turn_b_[size_t(e)];
    const double l = (1 - t) * len_a_[size_t(e)] + t * len_b_[size_t(e)];
    edges_[2 * size_t(e)] = std::cos(angle);
    edges_[2 * size_t(e) + 1] = std::sin(angle);
    gap_x += l * edges_[2 * size_t(e)];
    gap_y += l * edges_[2 * size_t(e) + 1];
  }
  // Closing a closed polygon: lengths change by S_e = −w_e² u_e·M⁻¹g, M = Σ w_e² u_e u_eᵀ, the least
  // Σ (S_e / w_e)² that makes the edges sum to zero.
  double lx = 0, ly = 0;
  if (closed_) {
    double m00 = 0, m01 = 0, m11 = 0;
    for (int e = 0; e < edges; ++e) {
      const double w2 = weight_[size_t(e)] * weight_[size_t(e)], ux = edges_[2 * size_t(e)],
                   uy = edges_[2 * size_t(e) + 1];
      m00 += w2 * ux * ux;
      m01 += w2 * ux * uy;
      m11 += w2 * uy * uy;
    }
    const double det = m00 * m11 - m01 * m01;
    if (det > 1e-300 && std::abs(det) > 1e-14 * (m00 * m11)) {
      lx = (m11 * gap_x - m01 * gap_y) / det;
      ly = (m00 * gap_y - m01 * gap_x) / det;
    }
  }
  double x = 0, y = 0, cx = 0, cy = 0;
  for (int e = 0; e < v; ++e) {
    const int p = polygon_[size_t(e)];
    out[2 * size_t(p)] = x;
    out[2 * size_t(p) + 1] = y;
    cx += x / v;
    cy += y / v;
    if (e >= edges) break;
    const double ux = edges_[2 * size_t(e)], uy = edges_[2 * size_t(e) + 1];
    const double w2 = weight_[size_t(e)] * weight_[size_t(e)];
    const double l = (1 - t) * len_a_[size_t(e)] + t * len_b_[size_t(e)] - w2 * (ux * lx + uy * ly);
    x += l * ux;
    y += l * uy;
  }
  const double tx = (1 - t) * centroid_a_[0] + t * centroid_b_[0] - cx;
  const double ty = (1 - t) * centroid_a_[1] + t * centroid_b_[1] - cy;
  for (int p : polygon_) {
    out[2 * size_t(p)] += tx;
    out[2 * size_t(p) + 1] += ty;
  }
}

}  // namespace splinekit::morph
