#include "correspondence.h"

#include <algorithm>
#include <cmath>

namespace splinekit::morph {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Ties (equal work up to rounding) go to the earlier candidate: a diagonal step before a one-sided
// one, a lower start before a higher one, forwards before backwards, so that rounding noise (as
// from moving both keys) cannot flip the choice between equally good paths.
double tie(double best) { return std::isfinite(best) ? 1e-11 * (1.0 + std::abs(best)) : 0.0; }

// Cost of one step into vertex (i2, j2) (relative indices), B shifted by `start`.
struct StepCosts {
  const ChainMeasure& a;
  const ChainMeasure& b;
  bool closed;
  int start;
  const WorkOptions& o;
  int m() const { return int(a.length.size()); }
  int n() const { return int(b.length.size()); }
  int ai(int i) const { return closed ? i % m() : i; }
  int bj(int j) const { return closed ? (j + start) % n() : j; }
  int aanchor(int i) const { return closed ? i % int(a.kink.size()) : i; }
  int banchor(int j) const { return closed ? (j + start) % int(b.kink.size()) : j; }
  // The kink paid at vertex (i, j) reached by a step that advanced A (da) and/or B (db).
  double kink(int i, int j, bool da, bool db) const {
    return kinking_work(da ? a.kink[size_t(ai(i))] : 0.0, db ? b.kink[size_t(bj(j))] : 0.0, o);
  }
  double both(int i, int j) const {  // from (i, j) to (i+1, j+1)
    const double la = a.length[size_t(ai(i))], lb = b.length[size_t(bj(j))];
    return stretching_work(la, lb, o) + bending_work(a.bending[size_t(ai(i))], b.bending[size_t(bj(j))], la, lb, o) +
           travel_work(la, lb, &a.middle[2 * size_t(ai(i))], &b.middle[2 * size_t(bj(j))], o) +
           kink(i + 1, j + 1, true, true);
  }
  double first(int i, int j) const {  // from (i, j) to (i+1, j)
    const double la = a.length[size_t(ai(i))];
    return stretching_work(la, 0, o) + bending_work(a.bending[size_t(ai(i))], 0, la, 0, o) +
           travel_work(la, 0, &a.middle[2 * size_t(ai(i))], &b.anchor[2 * size_t(banchor(j))], o) +
           kink(i + 1, j, true, false);
  }
  double second(int i, int j) const {  // from (i, j) to (i, j+1)
    const double lb = b.length[size_t(bj(j))];
    return stretching_work(0, lb, o) + bending_work(0, b.bending[size_t(bj(j))], 0, lb, o) +
           travel_work(0, lb, &a.anchor[2 * size_t(aanchor(i))], &b.middle[2 * size_t(bj(j))], o) +
           kink(i, j + 1, false, true);
  }
};

}  // namespace

int reversed_anchor(int b, int anchors, bool closed) { return closed ? (anchors - b) % anchors : anchors - 1 - b; }

double path_work(const ChainMeasure& a, const ChainMeasure& b, bool closed, int start, const std::vector<Move>& moves,
                 const WorkOptions& o) {
  const StepCosts c{a, b, closed, start, o};
  int i = 0, j = 0;
  double w = 0;
  for (Move mv : moves) {
    if (mv == Move::kBoth)
      w += c.both(i++, j++);
    else if (mv == Move::kFirst)
      w += c.first(i++, j);
    else
      w += c.second(i, j++);
  }
  if (i != c.m() || j != c.n()) return kInf;
  return w;
}

void CorrespondenceSearch::tables(const ChainMeasure& a, const ChainMeasure& b, bool closed, const WorkOptions& o) {
  travel_ = o.travel;
  // Start-independent parts: stretching + bending of every segment pair, and of each segment
  // against a point; kinks of every anchor pair and of each anchor against a straight point.
  const int m = int(a.length.size()), n = int(b.length.size());
  const int ma = int(a.kink.size()), nb = int(b.kink.size());
  diag_.resize(size_t(m) * n);
  for (int i = 0; i < m; ++i) {
    for (int j = 0; j < n; ++j) {
      const double la = a.length[size_t(i)], lb = b.length[size_t(j)];
      diag_[size_t(i) * n + j] = stretching_work(la, lb, o) +
                                 bending_work(a.bending[size_t(i)], b.bending[size_t(j)], la, lb, o) +
                                 travel_work(la, lb, &a.middle[2 * size_t(i)], &b.middle[2 * size_t(j)], o);
    }
  }
  kink_.resize(size_t(ma) * nb);
  for (int i = 0; i < ma; ++i)
    for (int j = 0; j < nb; ++j) kink_[size_t(i) * nb + j] = kinking_work(a.kink[size_t(i)], b.kink[size_t(j)], o);
  first_.resize(size_t(m));
  for (int i = 0; i < m; ++i) {
    const double la = a.length[size_t(i)];
    first_[size_t(i)] = stretching_work(la, 0, o) + bending_work(a.bending[size_t(i)], 0, la, 0, o) +
                        kinking_work(a.kink[size_t(closed ? (i + 1) % ma : i + 1)], 0, o);
  }
  second_.resize(size_t(n));
  for (int j = 0; j < n; ++j) {
    const double lb = b.length[size_t(j)];
    second_[size_t(j)] = stretching_work(0, lb, o) + bending_work(0, b.bending[size_t(j)], 0, lb, o) +
                         kinking_work(0, b.kink[size_t(closed ? (j + 1) % nb : j + 1)], o);
  }
  if (!closed) return;
  // Closed chains: whole step costs by (A index, B index), so the banded search reads one number
  // per step: a diagonal with the kink it reaches, a one-sided step with its travel.
  both_.resize(size_t(m) * n);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < n; ++j)
      both_[size_t(i) * n + j] = diag_[size_t(i) * n + j] + kink_[size_t((i + 1) % ma) * nb + size_t((j + 1) % nb)];
  first_at_.resize(size_t(m) * nb);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < nb; ++j)
      first_at_[size_t(i) * nb + j] = first_[size_t(i)] + travel_work(a.length[size_t(i)], 0, &a.middle[2 * size_t(i)],
                                                                      &b.anchor[2 * size_t(j)], o);
  second_at_.resize(size_t(ma) * n);
  for (int i = 0; i < ma; ++i)
    for (int j = 0; j < n; ++j)
      second_at_[size_t(i) * n + j] = second_[size_t(j)] + travel_work(0, b.length[size_t(j)], &a.anchor[2 * size_t(i)],
                                                                       &b.middle[2 * size_t(j)], o);
}

double CorrespondenceSearch::solve_band(int m, int n, int start, const std::vector<int>& lo, const std::vector<int>& hi,
                                        std::vector<int>& path_lo, std::vector<int>& path_hi) {
  const int ma = m, nb = n;  // closed: as many anchors as segments
  const size_t w = size_t(n) + 1;
  cost_.resize((size_t(m) + 1) * w);
  step_.resize((size_t(m) + 1) * w);
  row_lo_.resize(size_t(m) + 1);
  row_hi_.resize(size_t(m) + 1);
  int64_t cells = 0;
  for (int i = 0; i <= m; ++i) {
    const int L = std::max(0, lo[size_t(i)] - start), H = std::min(n, hi[size_t(i)] - start);
    row_lo_[size_t(i)] = L;
    row_hi_[size_t(i)] = H;
    const int pL = i > 0 ? row_lo_[size_t(i - 1)] : 1, pH = i > 0 ? row_hi_[size_t(i - 1)] : 0;
    double* row = &cost_[size_t(i) * w];
    const double* prev = i > 0 ? &cost_[size_t(i - 1) * w] : nullptr;
    int8_t* how_row = &step_[size_t(i) * w];
    for (int j = L; j <= H; ++j) {
      ++cells;
      if (i == 0 && j == 0) {
        row[0] = 0;
        how_row[0] = -1;
        continue;
      }
      double best = kInf;
      int8_t how = -1;
      const int js = (j - 1 + start) % n;  // B's segment before column j
      if (i > 0 && j > 0 && j - 1 >= pL && j - 1 <= pH) {
        const double c = prev[j - 1] + both_[size_t(i - 1) * n + size_t(js)];
        if (c < best) best = c, how = int8_t(Move::kBoth);
      }
      if (i > 0 && j >= pL && j <= pH) {
        const double c = prev[j] + first_at_[size_t(i - 1) * nb + size_t((j + start) % nb)];
        if (c < best - tie(best)) best = c, how = int8_t(Move::kFirst);
      }
      if (j > L) {
        const double c = row[j - 1] + second_at_[size_t(i % ma) * n + size_t(js)];
        if (c < best - tie(best)) best = c, how = int8_t(Move::kSecond);
      }
      row[j] = best;
      how_row[j] = how;
    }
  }
  counters_.cells += cells;
  counters_.starts += 1;
  const double total = row_hi_[size_t(m)] == n ? cost_[size_t(m) * w + size_t(n)] : kInf;
  // The path's columns per row (absolute), the bounds of the starts on either side of this one.
  path_lo.assign(size_t(m) + 1, std::numeric_limits<int>::max());
  path_hi.assign(size_t(m) + 1, std::numeric_limits<int>::min());
  if (std::isfinite(total)) {
    int i = m, j = n;
    while (true) {
      path_lo[size_t(i)] = std::min(path_lo[size_t(i)], j + start);
      path_hi[size_t(i)] = std::max(path_hi[size_t(i)], j + start);
      if (i == 0 && j == 0) break;
      const Move mv = Move(step_[size_t(i) * w + size_t(j)]);
      if (mv != Move::kSecond) --i;
      if (mv != Move::kFirst) --j;
    }
  }
  return total;
}

double CorrespondenceSearch::solve_start(const ChainMeasure& a, const ChainMeasure& b, bool closed, int start,
                                         const std::vector<AnchorPin>& pins, const WorkOptions& o,
                                         std::vector<Move>* moves) {
  tables(a, b, closed, o);
  return solve(a, b, closed, start, pins, moves);
}

double CorrespondenceSearch::solve(const ChainMeasure& a, const ChainMeasure& b, bool closed, int start,
                                   const std::vector<AnchorPin>& pins, std::vector<Move>* moves) {
  const int m = int(a.length.size()), n = int(b.length.size());
  const int nb = int(b.kink.size());
  const size_t w = size_t(n) + 1;
  cost_.assign((size_t(m) + 1) * w, kInf);
  step_.assign((size_t(m) + 1) * w, -1);
  // Pins relative to this start: vertex (pa, pb) must be on the path.
  auto allowed = [&](int i, int j) {
    for (const AnchorPin& p : pins) {
      const int pb = closed ? ((p.b - start) % n + n) % n : p.b;
      const int pa = p.a;
      if (closed && pa == 0) {
        if (pb != 0) return false;
        continue;
      }
      if (!((i <= pa && j <= pb) || (i >= pa && j >= pb))) return false;
    }
    return true;
  };
  auto bseg = [&](int j) { return closed ? (j + start) % n : j; };
  auto banchor = [&](int j) { return closed ? (j + start) % nb : j; };
  // With pins, a step must stay on one side of each pinned vertex (a diagonal cannot jump it).
  auto step_ok = [&](int i0, int j0, int i, int j) {
    for (const AnchorPin& p : pins) {
      const int pb = closed ? ((p.b - start) % n + n) % n : p.b;
      if (closed && p.a == 0) continue;
      const bool before = i0 <= p.a && j0 <= pb && i <= p.a && j <= pb;
      const bool after = i0 >= p.a && j0 >= pb && i >= p.a && j >= pb;
      if (!before && !after) return false;
    }
    return true;
  };
  cost_[0] = allowed(0, 0) ? 0.0 : kInf;
  for (int i = 0; i <= m; ++i) {
    for (int j = 0; j <= n; ++j) {
      if (i == 0 && j == 0) continue;
      if (!pins.empty() && !allowed(i, j)) continue;
      double best = kInf;
      int8_t how = -1;
      const bool pinned = !pins.empty();
      if (i > 0 && j > 0 && (!pinned || step_ok(i - 1, j - 1, i, j))) {
        const double k = kink_[size_t(closed ? i % int(a.kink.size()) : i) * nb + size_t(banchor(j))];
        const double c = cost_[size_t(i - 1) * w + size_t(j - 1)] + diag_[size_t(i - 1) * n + size_t(bseg(j - 1))] + k;
        if (c < best) best = c, how = int8_t(Move::kBoth);
      }
      if (i > 0 && (!pinned || step_ok(i - 1, j, i, j))) {
        double step = first_[size_t(i - 1)];
        if (travel_ > 0) {
          // Travel of A's segment i−1 to B's anchor j (inline: it depends on both).
          const double* p = &a.middle[2 * size_t(i - 1)];
          const double* q = &b.anchor[2 * size_t(banchor(j))];
          step +=
              travel_ * 0.5 * a.length[size_t(i - 1)] * ((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]));
        }
        const double c = cost_[size_t(i - 1) * w + size_t(j)] + step;
        if (c < best - tie(best)) best = c, how = int8_t(Move::kFirst);
      }
      if (j > 0 && (!pinned || step_ok(i, j - 1, i, j))) {
        double step = second_[size_t(bseg(j - 1))];
        if (travel_ > 0) {
          const double* p = &a.anchor[2 * size_t(closed ? i % int(a.kink.size()) : i)];
          const double* q = &b.middle[2 * size_t(bseg(j - 1))];
          step += travel_ * 0.5 * b.length[size_t(bseg(j - 1))] *
                  ((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]));
        }
        const double c = cost_[size_t(i) * w + size_t(j - 1)] + step;
        if (c < best - tie(best)) best = c, how = int8_t(Move::kSecond);
      }
      cost_[size_t(i) * w + size_t(j)] = best;
      step_[size_t(i) * w + size_t(j)] = how;
    }
  }
  counters_.cells += int64_t(m + 1) * (n + 1);
  counters_.starts += 1;
  const double total = cost_[size_t(m) * w + size_t(n)];
  if (moves && std::isfinite(total)) {
    moves->clear();
    int i = m, j = n;
    while (i > 0 || j > 0) {
      const Move mv = Move(step_[size_t(i) * w + size_t(j)]);
      moves->push_back(mv);
      if (mv != Move::kSecond) --i;
      if (mv != Move::kFirst) --j;
    }
    std::reverse(moves->begin(), moves->end());
  }
  return total;
}

Correspondence CorrespondenceSearch::search(const ChainMeasure& a, const ChainMeasure& b_forward,
                                            const ChainMeasure& b_backward, bool closed,
                                            const std::vector<AnchorPin>& pins, const WorkOptions& o, int directions) {
  Correspondence best;
  const int n = int(b_forward.length.size());
  const int nb = int(b_forward.kink.size());
  for (int dir = 0; dir < 2; ++dir) {
    if (!(directions & (dir == 0 ? kForward : kBackward))) continue;
    const ChainMeasure& b = dir == 0 ? b_forward : b_backward;
    std::vector<AnchorPin> p = pins;
    if (dir == 1)
      for (AnchorPin& q : p) q.b = reversed_anchor(q.b, nb, closed);
    const int starts = closed ? n : 1;
    tables(a, b, closed, o);
    if (closed && p.empty() && n > 1) {
      // Every start by divide and conquer over starts (Maes 1990): least-work paths of different
      // starts can be taken not to cross, so the path of start s lies between those of the starts
      // around it, and each level of the recursion relaxes O(m n) cells: O(m n log n) in all.
      const int m = int(a.length.size());
      std::vector<int> full_lo(size_t(m) + 1, 0), full_hi(size_t(m) + 1, 2 * n);
      std::vector<int> lo0, hi0;
      auto consider = [&](int s, double w) {
        if (w < best.work - tie(best.work) ||
            (std::abs(w - best.work) <= tie(best.work) && best.reversed == (dir == 1) && s < best.start)) {
          best.work = w;
          best.start = s;
          best.reversed = dir == 1;
        }
      };
      consider(0, solve_band(m, n, 0, full_lo, full_hi, lo0, hi0));
      std::vector<int> lon = lo0, hin = hi0;
      for (int& v : lon) v += n;
      for (int& v : hin) v += n;
      // Explicit stack of (s_lo, s_hi) with the bounds of their paths.
      struct Range {
        int s_lo, s_hi;
        std::vector<int> lo_of_lo, hi_of_hi;
      };
      std::vector<Range> stack;
      stack.push_back({0, n, lo0, hin});
      std::vector<int> plo, phi;
      while (!stack.empty()) {
        Range r = std::move(stack.back());
        stack.pop_back();
        if (r.s_hi - r.s_lo <= 1) continue;
        const int mid = (r.s_lo + r.s_hi) / 2;
        const double w = solve_band(m, n, mid, r.lo_of_lo, r.hi_of_hi, plo, phi);
        consider(mid, w);
        if (!std::isfinite(w)) {
          // No path inside the band (cannot happen when paths do not cross): fall back to the full grid.
          consider(mid, solve_band(m, n, mid, full_lo, full_hi, plo, phi));
        }
        stack.push_back({r.s_lo, mid, r.lo_of_lo, phi});
        stack.push_back({mid, r.s_hi, plo, r.hi_of_hi});
      }
    } else {
      for (int s = 0; s < starts; ++s) {
        const double w = solve(a, b, closed, s, p, nullptr);
        if (w < best.work - tie(best.work)) {
          best.work = w;
          best.start = s;
          best.reversed = dir == 1;
        }
      }
    }
  }
  if (std::isfinite(best.work)) {
    std::vector<AnchorPin> p = pins;
    if (best.reversed)
      for (AnchorPin& q : p) q.b = reversed_anchor(q.b, nb, closed);
    best.work = solve_start(a, best.reversed ? b_backward : b_forward, closed, best.start, p, o, &best.moves);
  }
  return best;
}

}  // namespace splinekit::morph
