// splinekit — the active window of localized editing (Eyiyurekli & Breen §3.1).
//
// The window spans `left` control points before the dragged point and `right` after it. On an
// open curve each side is clamped at the curve's end; on a closed curve it wraps across the seam,
// and when left + right reaches the point count the window is the whole loop: both sides end at
// the same control point (split in proportion to the request). The window's end points are the
// last points of each side; they get weight 0, so they and everything outside stay put.
#pragma once

#include <string>

namespace splinekit::edit {

struct ActiveWindow {
  int center = 0;  // the dragged control point
  int left = 0;    // points on the left side after clamping (the left end is center - left)
  int right = 0;   // points on the right side after clamping (the right end is center + right)
  int count = 0;   // control points of the curve
  bool closed = false;

  // Points in the window, both ends included (a whole closed loop counts its shared end twice).
  int size() const { return left + right + 1; }
  // Control point index of window slot k in [0, size()): k = left is the center.
  int index(int k) const {
    const int i = center - left + k;
    return closed ? ((i % count) + count) % count : i;
  }
};

// Resolves a requested window. Returns "" or a message naming the problem (center out of range,
// a negative side); `out` is written only on success.
std::string resolve_window(int count, bool closed, int center, int left, int right, ActiveWindow& out);

}  // namespace splinekit::edit
