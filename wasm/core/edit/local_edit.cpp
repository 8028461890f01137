#include "edit/local_edit.h"

#include <cmath>

namespace splinekit::edit {

std::string LocalEdit::begin(const CatmullRom& curve, int center, const EditOptions& options) {
  if (curve.count() == 0) return "the curve has no control points";
  ActiveWindow w;
  if (std::string e = resolve_window(curve.count(), curve.closed(), center, options.left, options.right, w); !e.empty())
    return e;
  if (!(options.falloff.alpha > 0.0) || !std::isfinite(options.falloff.alpha))
    return "alpha must be a positive number, got " + std::to_string(options.falloff.alpha);
  if (!(options.falloff.sigma > 0.0) || !std::isfinite(options.falloff.sigma))
    return "sigma must be a positive number, got " + std::to_string(options.falloff.sigma);
  window_ = w;
  options_ = options;
  base_ = curve.points();
  points_ = base_;
  const int slots = w.size();
  index_.resize(size_t(slots));
  u_.assign(size_t(slots), 0.0);
  weight_.assign(size_t(slots), 0.0);
  for (int k = 0; k < slots; ++k) index_[size_t(k)] = w.index(k);

  // Arc-length distance from the center to every point of each side, then u = d / W.
  const double tiny = 1e-14 * std::max(curve.size(), 1e-300);
  for (int side = 0; side < 2; ++side) {
    const int n = side == 0 ? w.left : w.right;
    if (n == 0) continue;
    double d = 0.0;
    for (int j = 1; j <= n; ++j) {
      const int k = side == 0 ? w.left - j : w.left + j;
      // The segment between slot k and its neighbour towards the center.
      const int segment = side == 0 ? w.center - j : w.center + j - 1;
      d += curve.segment_length(curve.closed() ? ((segment % w.count) + w.count) % w.count : segment);
      u_[size_t(k)] = d;
    }
    for (int j = 1; j <= n; ++j) {
      const int k = side == 0 ? w.left - j : w.left + j;
      // Coincident points have no length to share: fall back to the index fraction.
      u_[size_t(k)] = d > tiny ? u_[size_t(k)] / d : double(j) / n;
    }
    u_[size_t(side == 0 ? 0 : slots - 1)] = 1.0;  // the end, exactly
  }
  for (int k = 0; k < slots; ++k) weight_[size_t(k)] = k == w.left ? 1.0 : falloff(u_[size_t(k)], options.falloff);
  normal_[0] = curve.normal_at(index_.front());
  normal_[1] = curve.normal_at(index_.back());
  active_ = true;
  return "";
}

void LocalEdit::move(double dx, double dy) {
  if (index_.empty()) return;
  const int slots = int(index_.size()), c = window_.left;
  const double length = std::hypot(dx, dy);
  const bool turn = options_.normals && length > 0.0;
  Vec2 unit(1.0, 0.0);
  double angle[2] = {0.0, 0.0};
  if (turn) {
    unit = Vec2(dx, dy) / length;
    for (int side = 0; side < 2; ++side) {
      const Vec2 n = normal_[side].dot(unit) < 0.0 ? Vec2(-normal_[side]) : normal_[side];
      angle[side] = signed_angle(unit, n);
    }
  }
  for (int k = 0; k < slots; ++k) {
    if (k == c) continue;  // written last: on a whole closed loop an end shares its index
    const size_t i = size_t(index_[size_t(k)]);
    const double s = weight_[size_t(k)];
    double ox = 0.0, oy = 0.0;
    if (s != 0.0) {
      if (turn) {
        const double phi = u_[size_t(k)] * angle[k < c ? 0 : 1], co = std::cos(phi), si = std::sin(phi);
        ox = length * s * (co * unit.x() - si * unit.y());
        oy = length * s * (si * unit.x() + co * unit.y());
      } else {
        ox = s * dx;
        oy = s * dy;
      }
    }
    points_[2 * i] = base_[2 * i] + ox;
    points_[2 * i + 1] = base_[2 * i + 1] + oy;
  }
  const size_t i = size_t(index_[size_t(c)]);
  points_[2 * i] = base_[2 * i] + dx;
  points_[2 * i + 1] = base_[2 * i + 1] + dy;
}

}  // namespace splinekit::edit
