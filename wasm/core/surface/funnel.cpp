#include "surface/funnel.h"

#include <algorithm>

namespace splinekit::surface {

namespace {

// A point of the funnel's two chains: where it lies, its mesh vertex and the last portal it bounds.
struct ChainPoint {
  Vec2 pos;
  int vertex, portal;
};

}  // namespace

// The funnel is kept as its two chains, in one array: the left chain from its newest point
// chain[lo] to the apex chain[ap], the right chain from the apex to its newest point chain[hi].
// Each chain turns one way (the left one left, the right one right); a new portal end point pops
// the points it sees past, and when it sees past the apex too it crosses the other chain, whose
// points it passes become apices. Every portal is thus looked at once (the "simple stupid" form,
// which keeps one point per side, looks again at the portals after each new apex).
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
  static thread_local std::vector<ChainPoint> chain;
  const size_t size = 2 * static_cast<size_t>(n) + 4;
  if (chain.size() < size) chain.resize(size);
  int lo = 0, ap = 0, hi = 0;
  // The funnel's state once apices.back() is the apex: the chains hold it alone.
  auto restart = [&]() {
    const Apex& x = apices.back();
    lo = ap = hi = n + 2;
    chain[ap] = {x.pos, x.vertex, x.portal};
  };
  restart();
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
  // A stretch between changes: once the apex just made is a known one there, the known apices made
  // by the stretch's portals follow it (moved); false when none does.
  size_t stretch = 0;
  auto take_known = [&]() {
    const Apex& x = apices.back();
    if (!splice || x.vertex < 0) return false;
    const std::vector<Splice::Agreement>& between = splice->between;
    while (stretch < between.size() && between[stretch].to <= x.portal) ++stretch;
    if (stretch == between.size() || x.portal < between[stretch].from) return false;
    const Splice::Agreement& g = between[stretch];
    const std::vector<Apex>& known = *splice->path;
    const int at = x.portal + g.shift;
    const auto y = std::lower_bound(known.begin(), known.end(), at, [](const Apex& a, int p) { return a.portal < p; });
    if (y == known.end() || y->portal != at || y->vertex != x.vertex) return false;
    const size_t before = apices.size();
    for (auto k = y + 1; k != known.end() && k->vertex >= 0 && k->emitted < g.to + g.shift; ++k)
      apices.push_back({g.motion(k->pos), k->vertex, k->portal - g.shift, k->emitted - g.shift});
    return apices.size() > before;
  };
  // A point of the chains becomes an apex at portal i: kGo on, kJumped (the known path took over up
  // to apices.back(): restart there), kDone (it took over to the end).
  enum class Made { kGo, kJumped, kDone };
  auto make = [&](const ChainPoint& c, int i) {
    apices.push_back({c.pos, c.vertex, c.portal, i});
    if (const size_t y = known_from()) {
      finish_known(y);
      return Made::kDone;
    }
    return take_known() ? Made::kJumped : Made::kGo;
  };
  // Portal i's end points, right then left (as the funnel tightens its right side first). Every
  // portal of a pass's trial strip goes through these two (most of phase (iii)'s funnel work):
  // inlined, the chains' ends lo, ap, hi stay in registers instead of being read and written
  // through the closure (-15% of the funnel's instructions natively).
  auto add_right = [&](const Vec2& R, int rv, int i) __attribute__((always_inline)) {
    if (R == chain[ap].pos) return Made::kGo;  // (the apex itself)
    while (hi > ap && orient(chain[hi - 1].pos, chain[hi].pos, R) >= 0) --hi;
    while (hi == ap && ap > lo && orient(chain[ap].pos, chain[ap - 1].pos, R) >= 0) {
      // R crosses over the left chain: its first point becomes the apex.
      hi = --ap;
      if (const Made m = make(chain[ap], i); m != Made::kGo) return m;
    }
    chain[++hi] = {R, rv, i};
    return Made::kGo;
  };
  auto add_left = [&](const Vec2& L, int lv, int i) __attribute__((always_inline)) {
    if (L == chain[ap].pos) return Made::kGo;
    while (lo < ap && orient(chain[lo + 1].pos, chain[lo].pos, L) <= 0) ++lo;
    while (lo == ap && ap < hi && orient(chain[ap].pos, chain[ap + 1].pos, L) <= 0) {
      lo = ++ap;
      if (const Made m = make(chain[ap], i); m != Made::kGo) return m;
    }
    chain[--lo] = {L, lv, i};
    return Made::kGo;
  };
  // Consecutive portals share an end point (the strip turns about one vertex at a time). Added
  // again, that point would pop itself off its chain's end and come back (or it is the apex, and
  // is skipped): only the portal it bounds last is renewed. Half the end points, a third of the
  // funnel's instructions on the folded body of BENCHMARKS.md (the same apices).
  const Vec2* last_right = nullptr;
  const Vec2* last_left = nullptr;
  for (int i = apices.back().portal + 1; i <= n; ++i) {
    Made m = Made::kGo;
    if (i < n) {
      const Vec2 &R = u.right(i), &L = u.left(i);
      if (last_right && R == *last_right) {
        if (hi > ap) chain[hi].portal = i;
      } else {
        m = add_right(R, u.portals[i].right_vertex, i);
      }
      if (m == Made::kGo) {
        if (last_left && L == *last_left) {
          if (lo < ap) chain[lo].portal = i;
        } else {
          m = add_left(L, u.portals[i].left_vertex, i);
        }
      }
      last_right = &R, last_left = &L;
    } else {  // the target: the path to it is the apex's right chain once it joins it
      if (target == chain[ap].pos) break;
      m = add_right(target, -1, n);
      if (m == Made::kGo) {
        for (int k = ap + 1; k < hi && m == Made::kGo; ++k) m = make(chain[k], n);
        if (m == Made::kGo) break;
      }
    }
    if (m == Made::kDone) return;
    if (m == Made::kJumped) {
      restart();
      i = apices.back().portal;
      last_right = last_left = nullptr;
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
