#include "surface/funnel.h"

#include <algorithm>

namespace splinekit::surface {

void funnel(const UnfoldedStrip& u, const Vec2& source, const Vec2& target, std::vector<Apex>& apices,
            const Splice* splice) {
  const int n = static_cast<int>(u.portals.size());
  apices.clear();
  apices.push_back({source, -1, -1, -1});
  if (splice) {
    const std::vector<Apex>& known = *splice->path;
    size_t m = 0;
    while (m + 2 < known.size() && known[m + 1].emitted < splice->lo) ++m;
    apices.insert(apices.end(), known.begin() + 1, known.begin() + m + 1);
  }
  Vec2 apex = apices.back().pos, left = apex, right = apex;
  int apex_index = apices.back().portal, left_index = apex_index, right_index = apex_index;
  int left_vertex = apices.back().vertex, right_vertex = left_vertex;
  // The known path's apex that the one just made is, past `hi`, or 0.
  auto known_from = [&]() -> size_t {
    const Apex& x = apices.back();
    if (!splice || x.portal < splice->hi || x.vertex < 0) return 0;
    const std::vector<Apex>& known = *splice->path;
    const int at = x.portal + splice->shift;
    const auto y = std::lower_bound(known.begin(), known.end(), at, [](const Apex& a, int p) { return a.portal < p; });
    return y != known.end() && y->portal == at && y->vertex == x.vertex ? static_cast<size_t>(y - known.begin()) : 0;
  };
  auto finish_known = [&](size_t y) {
    const std::vector<Apex>& known = *splice->path;
    for (size_t k = y + 1; k < known.size(); ++k)
      apices.push_back({splice->motion(known[k].pos), known[k].vertex, known[k].portal - splice->shift,
                        known[k].emitted - splice->shift});
    apices.back().pos = target;
  };
  for (int i = apex_index + 1; i <= n; ++i) {
    const Vec2 L = i < n ? u.left(i) : target;
    const Vec2 R = i < n ? u.right(i) : target;
    const int lv = i < n ? u.portals[i].left_vertex : -1;
    const int rv = i < n ? u.portals[i].right_vertex : -1;
    // Right side: tighten when R is left of (or on) apex->right.
    if (orient(apex, right, R) >= 0) {
      if (apex == right || apex == left || orient(apex, left, R) < 0) {
        right = R;
        right_index = i;
        right_vertex = rv;
      } else {
        // R crosses over the left side: the left point becomes the apex.
        apices.push_back({left, left_vertex, left_index, i});
        if (const size_t y = known_from()) return finish_known(y);
        apex = left;
        apex_index = left_index;
        right = left = apex;
        right_index = left_index = apex_index;
        right_vertex = left_vertex;
        i = apex_index;
        continue;
      }
    }
    // Left side: tighten when L is right of (or on) apex->left.
    if (orient(apex, left, L) <= 0) {
      if (apex == left || apex == right || orient(apex, right, L) > 0) {
        left = L;
        left_index = i;
        left_vertex = lv;
      } else {
        apices.push_back({right, right_vertex, right_index, i});
        if (const size_t y = known_from()) return finish_known(y);
        apex = right;
        apex_index = right_index;
        left = right = apex;
        left_index = right_index = apex_index;
        left_vertex = right_vertex;
        i = apex_index;
        continue;
      }
    }
  }
  if (apices.back().pos == target && apices.size() > 1) apices.pop_back();
  apices.push_back({target, -1, n, n});
}

// Drops the apices where the funnel's path goes straight on but for rounding (a vertex on the line
// between its neighbours): they would stand in for the real bends next to them.
void drop_straight(std::vector<Apex>& apices) {
  size_t kept = 1;
  for (size_t j = 1; j + 1 < apices.size(); ++j) {
    const Vec2 a = apices[j].pos - apices[kept - 1].pos, b = apices[j + 1].pos - apices[j].pos;
    if (std::abs(cross(a, b)) > 1e-12 * a.norm() * b.norm() || a.dot(b) < 0) apices[kept++] = apices[j];
  }
  apices[kept++] = apices.back();
  apices.resize(kept);
}

// Lerps on every portal from the funnel's polyline, and the arc length at each point of the path
// (start, crossings, end).
void crossings(const UnfoldedStrip& u, const std::vector<Apex>& apices, std::vector<double>& lerps,
               std::vector<double>& arc) {
  const int n = static_cast<int>(u.portals.size());
  lerps.resize(n);
  arc.resize(n + 2);
  arc[0] = 0;
  Vec2 prev = apices.front().pos;
  size_t j = 0;
  for (int i = 0; i < n; ++i) {
    while (j + 1 < apices.size() && apices[j + 1].portal < i) ++j;
    const Vec2& q = apices[j].pos;
    const Vec2 d = apices[j + 1].pos - q;
    const Vec2& R = u.right(i);
    const Vec2& L = u.left(i);
    const double den = cross(d, L - R);
    double s = std::abs(den) > 0 ? cross(d, q - R) / den : 0.5;
    if (!(s >= 0)) s = 0;
    if (s > 1) s = 1;
    lerps[i] = s;
    const Vec2 at = R + s * (L - R);
    arc[i + 1] = arc[i] + (at - prev).norm();
    prev = at;
  }
  arc[n + 1] = arc[n] + (apices.back().pos - prev).norm();
}

}  // namespace splinekit::surface
