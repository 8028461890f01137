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

namespace {

// cos and sin of a small angle (|x| < 0.1) by their Taylor series to x^10: error below 1e-19.
inline void small_sincos(double x, double& c, double& s) {
  // Horner in x² with the reciprocals as constants (a division per term would cost more than the rest).
  constexpr double k2 = 1.0 / 2, k12 = 1.0 / 12, k30 = 1.0 / 30, k56 = 1.0 / 56, k90 = 1.0 / 90;
  constexpr double k6 = 1.0 / 6, k20 = 1.0 / 20, k42 = 1.0 / 42, k72 = 1.0 / 72, k110 = 1.0 / 110;
  const double x2 = x * x;
  c = 1.0 - x2 * k2 * (1.0 - x2 * k12 * (1.0 - x2 * k30 * (1.0 - x2 * k56 * (1.0 - x2 * k90))));
  s = x * (1.0 - x2 * k6 * (1.0 - x2 * k20 * (1.0 - x2 * k42 * (1.0 - x2 * k72 * (1.0 - x2 * k110)))));
}

// Every this many points the running rotation is recomputed exactly (bounds rounding drift).
constexpr int kResync = 64;

}  // namespace

void LocalEdit::move(double dx, double dy) {
  if (index_.empty()) return;
  const int slots = int(index_.size()), c = window_.left;
  const double length = std::hypot(dx, dy);
  const bool turn = options_.normals && length > 0.0;
  auto place = [&](int k, double ox, double oy) {
    const size_t i = size_t(index_[size_t(k)]);
    points_[2 * i] = base_[2 * i] + ox;
    points_[2 * i + 1] = base_[2 * i + 1] + oy;
  };
  if (!turn) {
    for (int k = 0; k < slots; ++k) {
      if (k == c) continue;  // written last: on a whole closed loop an end shares its index
      const double s = weight_[size_t(k)];
      place(k, s * dx, s * dy);
    }
  } else {
    // Each point's direction is D̂ turned by u·angle towards its side's normal. Walking outwards
    // from the center, u grows a little per point: the rotation is carried along by small steps
    // (two multiplications and a short series each) instead of a sine and a cosine per point.
    const Vec2 unit = Vec2(dx, dy) / length;
    for (int side = 0; side < 2; ++side) {
      const Vec2 n = normal_[side].dot(unit) < 0.0 ? Vec2(-normal_[side]) : normal_[side];
      const double angle = signed_angle(unit, n);
      const int count = side == 0 ? c : slots - 1 - c, step = side == 0 ? -1 : 1;
      double co = 1.0, si = 0.0, u_prev = 0.0;
      for (int j = 1; j <= count; ++j) {
        const int k = c + step * j;
        const double u = u_[size_t(k)], x = (u - u_prev) * angle;
        if (j % kResync == 0 || std::abs(x) >= 0.1) {
          co = std::cos(u * angle);
          si = std::sin(u * angle);
        } else {
          double cx, sx;
          small_sincos(x, cx, sx);
          const double c2 = co * cx - si * sx;
          si = si * cx + co * sx;
          co = c2;
        }
        u_prev = u;
        const double s = weight_[size_t(k)];
        if (s == 0.0) {
          place(k, 0.0, 0.0);
        } else {
          place(k, length * s * (co * unit.x() - si * unit.y()), length * s * (si * unit.x() + co * unit.y()));
        }
      }
    }
  }
  place(c, dx, dy);
}

}  // namespace splinekit::edit
