#include "edit/active_window.h"

#include <algorithm>
#include <cmath>

namespace splinekit::edit {

std::string resolve_window(int count, bool closed, int center, int left, int right, ActiveWindow& out) {
  if (count < 1) return "the curve has no control points";
  if (center < 0 || center >= count) {
    return "control point " + std::to_string(center) + " is out of range (the curve has " + std::to_string(count) +
           " control points: 0.." + std::to_string(count - 1) + ")";
  }
  if (left < 0 || right < 0) {
    return "the window's sides must not be negative, got " + std::to_string(left) + " and " + std::to_string(right);
  }
  ActiveWindow w;
  w.center = center;
  w.count = count;
  w.closed = closed;
  if (!closed) {
    w.left = std::min(left, center);
    w.right = std::min(right, count - 1 - center);
  } else if (long(left) + long(right) >= long(count)) {
    // The whole loop: both sides end at one control point, split as requested.
    w.left = int(std::lround(double(count) * double(left) / (double(left) + double(right))));
    w.left = std::clamp(w.left, 0, count);
    w.right = count - w.left;
  } else {
    w.left = left;
    w.right = right;
  }
  out = w;
  return "";
}

}  // namespace splinekit::edit
