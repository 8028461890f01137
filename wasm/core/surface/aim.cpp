#include "surface/aim.h"

#include <algorithm>
#include <cmath>

namespace splinekit::surface {

namespace {

enum class Shot { kFailed, kReached, kPassed };

// One shot: the line from o in direction d walked from u's first face until it enters end.face
// (kReached) or its exit edge lies wholly beyond `reach` along it (kPassed: `miss` is the sine of
// the angle from d to where the face it passed in puts the end point, and `reach` becomes that
// point's distance from o). kFailed at a boundary, a vertex on the line, or past `cap` faces.
Shot walk(const TriMesh& mesh, const UnfoldedStrip& u, const Vec2& o, const Vec2& d, const MeshPoint& end,
          const Vec3& target, size_t cap, double& reach, double& miss, std::vector<int>& faces) {
  faces.assign(1, u.faces.front());
  int f = u.faces.front();
  std::array<Vec2, 3> cf = u.corners.front(), cg;
  const double length = d.norm();
  while (f != end.face) {
    // Left through the edge from a corner on the line's right to one on its left.
    double side[3];
    for (int k = 0; k < 3; ++k) side[k] = cross(d, cf[k] - o);
    int e = -1;
    for (int k = 0; k < 3; ++k)
      if (side[k] < 0 && side[(k + 1) % 3] > 0) e = k;
    if (e < 0 || faces.size() > cap) return Shot::kFailed;
    const double beyond = 1.02 * reach * length;
    if ((cf[e] - o).dot(d) > beyond && (cf[(e + 1) % 3] - o).dot(d) > beyond) {
      Vec2 at;
      if (!lay_point(mesh, f, cf, target, at)) return Shot::kFailed;
      const Vec2 to = at - o;
      reach = to.norm();
      if (!(reach > 0)) return Shot::kFailed;
      miss = cross(d, to) / (length * reach);
      return Shot::kPassed;
    }
    const int g = mesh.adjacency[f][e];
    if (g < 0) return Shot::kFailed;
    lay_across(mesh, f, e, cf, cg);
    cf = cg, f = g;
    faces.push_back(f);
  }
  return Shot::kReached;
}

}  // namespace

bool aim(const TriMesh& mesh, const UnfoldedStrip& u, const MeshPoint& start, const MeshPoint& end, int shots,
         std::vector<int>& faces, int& fired) {
  const int n = static_cast<int>(u.faces.size());
  if (n < 2 || shots < 1 || end.face != u.faces.back()) return false;
  const Vec2 o = u.map(0, start), d0 = u.map(n - 1, end) - o;
  const Vec3 target = eval_position(mesh, end);
  const size_t cap = 2 * static_cast<size_t>(n) + 64;
  double reach = d0.norm();
  if (!(reach > 0)) return false;
  // The shot at angle θ from d0 (the line to where the strip's layout puts the end point).
  auto shoot = [&](double theta, double& miss) {
    ++fired;
    const double c = std::cos(theta), s = std::sin(theta);
    return walk(mesh, u, o, Vec2(c * d0.x() - s * d0.y(), s * d0.x() + c * d0.y()), end, target, cap, reach, miss,
                faces);
  };
  double theta = 0, miss = 0;
  Shot shot = shoot(theta, miss);
  // The last two shots (θ, miss), the one before's miss, and the bracket once misses change sign.
  double last_theta = 0, last_miss = 0, before_miss = HUGE_VAL;
  bool bracketed = false;
  double lo = 0, lo_miss = 0, hi = 0, hi_miss = 0;
  int kept_side = 0;  // which end the last two secant steps replaced (Illinois: halve the other's miss)
  for (int k = 1; shot == Shot::kPassed; ++k) {
    if (k >= shots || (k >= 3 && std::abs(miss) > 0.5 * std::abs(before_miss))) return false;
    double next;
    if (k == 1) {
      next = theta + std::asin(std::clamp(miss, -1.0, 1.0));  // at the point the face put the end at
    } else {
      if (!bracketed && (miss > 0) != (last_miss > 0)) {
        bracketed = true;
        lo = last_theta, lo_miss = last_miss, hi = theta, hi_miss = miss;
      } else if (bracketed) {
        if ((miss > 0) == (lo_miss > 0)) {
          lo = theta, lo_miss = miss;
          if (kept_side == -1) hi_miss /= 2;
          kept_side = -1;
        } else {
          hi = theta, hi_miss = miss;
          if (kept_side == 1) lo_miss /= 2;
          kept_side = 1;
        }
      }
      if (bracketed) {
        next = lo - lo_miss * (hi - lo) / (hi_miss - lo_miss);
      } else {
        next = miss != last_miss ? theta - miss * (theta - last_theta) / (miss - last_miss) : theta + miss;
        next = std::clamp(next, theta - 0.5, theta + 0.5);  // (a secant far out is no guide)
      }
    }
    if (!std::isfinite(next)) return false;
    before_miss = last_miss, last_theta = theta, last_miss = miss, theta = next;
    shot = shoot(theta, miss);
  }
  return shot == Shot::kReached;
}

}  // namespace splinekit::surface
