// splinekit — the small geometric kernels and constants every capability shares.
//
// One home for what was written several times across the core: π, the vector types, reading a
// point from a flat x,y array, and the 2D cross product with the orientation test built on it.
// Capabilities include this header instead of spelling their own; names say what they compute.
#pragma once

#include <Eigen/Core>
#include <cstddef>

namespace splinekit {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;

inline constexpr double kPi = 3.14159265358979323846;

// Point k of a flat array of x,y pairs: (xy[2k], xy[2k+1]).
inline Vec2 vec2_at(const double* xy, int k = 0) { return {xy[2 * size_t(k)], xy[2 * size_t(k) + 1]}; }

// The z component of the 3D cross product of (a, 0) and (b, 0): |a| |b| sin(angle from a to b).
// Positive when b lies counter-clockwise of a.
inline double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// Twice the signed area of triangle (a, b, c): positive when a, b, c turn counter-clockwise
// (c lies left of the directed line a → b), zero when collinear.
inline double orient(const Vec2& a, const Vec2& b, const Vec2& c) { return cross(b - a, c - a); }

}  // namespace splinekit
