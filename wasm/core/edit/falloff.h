// splinekit — the drop-off functions of localized Catmull-Rom editing (Eyiyurekli & Breen §3.3,
// equations 1–3) and the direction interpolation of §3.4.
//
// The paper's equations were lost in extraction; re-derived from its text. With d the arc-length
// distance along the curve from the dragged point and W the window's extent on that side, u = d / W
// in [0, 1], each S(u) falls from 1 at the dragged point to 0 at the window's end, monotonically:
//   linear (eq. 1):    S = 1 - u
//   Gaussian (eq. 2):  S = exp(-u² / (2σ²)) · f(u), σ a fraction of W; the Gaussian never reaches
//                      zero, so f = 1 up to ε = σ from the end and ½ (1 + cos(π (u - (1 - ε)) / ε))
//                      after it: f falls smoothly (C1) to 0 at u = 1
//   cosine (eq. 3):    S = cos(π u / 2)^α, α > 0 (α < 1 squares the bump off, α > 1 sharpens it)
#pragma once

#include "common/geometry.h"

namespace splinekit::edit {

// The numbers cross to TS (src/edit/local-edit.ts FALLOFFS).
enum class Falloff : int { kLinear = 0, kGaussian = 1, kCosine = 2 };

struct FalloffOptions {
  Falloff kind = Falloff::kCosine;  // the paper's choice (§3.3: "created the best results")
  double alpha = 1.0;               // exponent of the cosine (> 0)
  double sigma = 1.0 / 3.0;         // Gaussian width as a fraction of the side's extent W (> 0)
};

// The boundary function f of equation 2 at u (ε = σ): 1 for u <= 1 - ε, 0 at u >= 1.
double gaussian_boundary(double u, double sigma);

// S(u) for u = d / W; u is clamped to [0, 1].
double falloff(double u, const FalloffOptions& options);

// Spherical linear interpolation between unit 2D vectors a and b at t in [0, 1]:
// sin((1-t)θ)/sin θ · a + sin(tθ)/sin θ · b with θ the angle between them, which in the plane is a
// rotates by t times the signed angle from a to b. When b = -a (θ = 180°) the formula is 0/0 and
// every way round is as short: a turns counter-clockwise by t·π.
Vec2 slerp(const Vec2& a, const Vec2& b, double t);

// The signed angle from unit a to unit b in (-π, π], with π for the 180° case (as slerp turns).
double signed_angle(const Vec2& a, const Vec2& b);

}  // namespace splinekit::edit
