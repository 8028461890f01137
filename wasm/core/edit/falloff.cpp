#include "edit/falloff.h"

#include <algorithm>
#include <cmath>

namespace splinekit::edit {

double gaussian_boundary(double u, double sigma) {
  const double eps = std::clamp(sigma, 1e-9, 1.0);
  if (u <= 1.0 - eps) return 1.0;
  if (u >= 1.0) return 0.0;
  return 0.5 * (1.0 + std::cos(kPi * (u - (1.0 - eps)) / eps));
}

double falloff(double u, const FalloffOptions& options) {
  u = std::clamp(u, 0.0, 1.0);
  switch (options.kind) {
    case Falloff::kLinear:
      return 1.0 - u;
    case Falloff::kGaussian: {
      const double s = std::max(options.sigma, 1e-9);
      return std::exp(-u * u / (2.0 * s * s)) * gaussian_boundary(u, s);
    }
    case Falloff::kCosine:
    default: {
      if (u >= 1.0) return 0.0;  // cos(π/2) is 6e-17, not 0: the window's end must not move
      return std::pow(std::cos(0.5 * kPi * u), options.alpha);
    }
  }
}

double signed_angle(const Vec2& a, const Vec2& b) {
  const double c = cross(a, b), d = a.dot(b);
  if (c == 0.0 && d < 0.0) return kPi;
  return std::atan2(c, d);
}

Vec2 slerp(const Vec2& a, const Vec2& b, double t) {
  const double phi = t * signed_angle(a, b), c = std::cos(phi), s = std::sin(phi);
  return {c * a.x() - s * a.y(), s * a.x() + c * a.y()};
}

}  // namespace splinekit::edit
