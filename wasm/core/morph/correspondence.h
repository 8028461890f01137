// splinekit — the least-work correspondence of two chains (Sederberg & Greenwood 1992 §4 graph search,
// as extended to B-splines in the 1993 paper, §6).
//
// The graph has a row per distinct knot (anchor) of chain A and a column per anchor of chain B. A
// path from (0, 0) to (m, n) takes three kinds of steps:
//   kBoth   (i, j) → (i+1, j+1): segment i of A blends into segment j of B;
//   kFirst  (i, j) → (i+1, j):   segment i of A shrinks to B's anchor j (B gets a knot inserted there);
//   kSecond (i, j) → (i, j+1):   segment j of B grows from A's anchor i.
// Only knots that already exist are inserted (as in [10]), so a path is a set of knot insertions
// that gives both B-splines one knot structure. A step costs the stretching and bending work of
// its segments (eq. 3, 4, and the travel work of work.h) plus the kinking work (eq. 5) of the vertex it reaches, where
// an anchor the step does not advance counts as a straight point (θ = 0): each anchor of A and of B is paid for exactly
// once, at the vertex where the path first reaches it. The cost of a step then depends only on the step, so the
// least-work path is a shortest path in a grid DAG: O(m n).
//
// Closed chains: every cyclic start (B's anchor s matched to A's anchor 0) and, optionally, both
// directions of B are searched, by divide and conquer over the starts (least-work paths of
// different starts need not cross, so each bounds the others): O(m n log n) per direction;
// with pins, start by start, O(m n²). For closed chains the vertex (m, n) is
// (0, s) again, paid by the step that reaches it like any other: every vertex of the cyclic path is
// paid by its incoming step, so the work of a closed path does not depend on where it is cut, and
// the work of A → B equals that of B → A.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "work.h"

namespace splinekit::morph {

enum class Move : int8_t { kBoth = 0, kFirst = 1, kSecond = 2 };

// A pinned correspondence: anchor `a` of chain A must meet anchor `b` of chain B (the paper's
// anchor points, §5). Indices are anchors of the chains as given (forward B).
struct AnchorPin {
  int a = 0;
  int b = 0;
};

struct Correspondence {
  int start = 0;          // B's anchor matched to A's anchor 0 (in the searched direction of B)
  bool reversed = false;  // B is traversed backwards (closed or open)
  double work = std::numeric_limits<double>::infinity();
  std::vector<Move> moves;  // the path from (0, 0) to (m, n)
};

struct SearchCounters {
  int64_t cells = 0;  // grid cells relaxed over all starts and directions
  int starts = 0;     // (start, direction) pairs solved
};

class CorrespondenceSearch {
 public:
  // Least work with B's anchor `start` at A's anchor 0 (always 0 for open chains). `b` is measured
  // in the direction searched; pins are in that direction's anchor indices. Writes the path to
  // `moves` when given; returns +inf when no path satisfies the pins.
  double solve_start(const ChainMeasure& a, const ChainMeasure& b, bool closed, int start,
                     const std::vector<AnchorPin>& pins, const WorkOptions& options, std::vector<Move>* moves);

  // Every start (closed) in the directions of B given by `directions` (kForward | kBackward).
  // `b_backward` is the measure of reversed(B) (chain.h); pins are given in forward indices.
  Correspondence search(const ChainMeasure& a, const ChainMeasure& b_forward, const ChainMeasure& b_backward,
                        bool closed, const std::vector<AnchorPin>& pins, const WorkOptions& options, int directions);
  static constexpr int kForward = 1, kBackward = 2, kBoth = 3;

  const SearchCounters& counters() const { return counters_; }

 private:
  // The search for one start on the tables of the last tables() call.
  double solve(const ChainMeasure& a, const ChainMeasure& b, bool closed, int start, const std::vector<AnchorPin>& pins,
               std::vector<Move>* moves);
  void tables(const ChainMeasure& a, const ChainMeasure& b, bool closed, const WorkOptions& options);
  // Scratch, sized on use and kept between calls.
  std::vector<double> cost_, diag_, first_, second_, kink_;
  // Closed chains, divide and conquer over starts: one start inside column bounds per row
  // (absolute, unrolled B columns); writes the columns its path visits per row.
  double solve_band(int m, int n, int start, const std::vector<int>& lo, const std::vector<int>& hi,
                    std::vector<int>& path_lo, std::vector<int>& path_hi);
  std::vector<int8_t> step_;
  std::vector<double> both_, first_at_, second_at_;
  std::vector<int> row_lo_, row_hi_;
  double travel_ = 0;
  SearchCounters counters_;
};

// The work of one path, summed step by step (the definition the search minimises; tests compare
// the search against every path of small inputs).
double path_work(const ChainMeasure& a, const ChainMeasure& b, bool closed, int start, const std::vector<Move>& moves,
                 const WorkOptions& options);

// Anchor index in reversed(B) of B's anchor `b` (closed: (n − b) mod n, open: n − b).
int reversed_anchor(int b, int anchors, bool closed);

}  // namespace splinekit::morph
