#include "edit/sketch.h"

#include <algorithm>
#include <cmath>

#include "common/bezier.h"

namespace splinekit::edit {

namespace {

constexpr double kGaussNodes[3] = {-0.7745966692414833770, 0.0, 0.7745966692414833770};
constexpr double kGaussWeights[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
constexpr int kMaxPoints = 10000000;

}  // namespace

// ---------------------------------------------------------------------------------------------
// ArcLengthTable
// ---------------------------------------------------------------------------------------------

void ArcLengthTable::build(const CatmullRom& curve, int first, int segments) {
  seg_.resize(8 * size_t(segments));
  cum_.resize(size_t(kSub) * size_t(segments) + 1);
  cum_[0] = 0.0;
  for (int k = 0; k < segments; ++k) {
    curve.segment_bezier(first + k, seg_.data() + 8 * size_t(k));
    for (int j = 0; j < kSub; ++j) {
      const size_t at = size_t(kSub) * size_t(k) + size_t(j);
      cum_[at + 1] = cum_[at] + partial(k, double(j) / kSub, double(j + 1) / kSub);
    }
  }
}

double ArcLengthTable::partial(int segment, double ua, double ub) const {
  const double* c = seg_.data() + 8 * size_t(segment);
  const double half = 0.5 * (ub - ua), mid = 0.5 * (ua + ub);
  double sum = 0.0;
  for (int g = 0; g < 3; ++g) sum += kGaussWeights[g] * bezier_derivative(c, mid + half * kGaussNodes[g], 1).norm();
  return sum * half;
}

void ArcLengthTable::locate(double s, int& segment, double& u) const {
  const int cells = int(cum_.size()) - 1;
  s = std::clamp(s, 0.0, total());
  // The last cell whose start is <= s.
  int cell = int(std::upper_bound(cum_.begin(), cum_.end(), s) - cum_.begin()) - 1;
  cell = std::clamp(cell, 0, cells - 1);
  segment = cell / kSub;
  const double ua = double(cell % kSub) / kSub, ub = ua + 1.0 / kSub;
  const double r = s - cum_[size_t(cell)], length = cum_[size_t(cell) + 1] - cum_[size_t(cell)];
  u = length > 0.0 ? ua + (ub - ua) * std::min(r / length, 1.0) : ua;
  const double* c = seg_.data() + 8 * size_t(segment);
  for (int iteration = 0; iteration < 2; ++iteration) {
    const double speed = bezier_derivative(c, u, 1).norm();
    if (!(speed > 0.0)) break;
    u = std::clamp(u - (partial(segment, ua, u) - r) / speed, ua, ub);
  }
}

// ---------------------------------------------------------------------------------------------
// SketchCapture
// ---------------------------------------------------------------------------------------------

std::string SketchCapture::capture(const double* samples, int n, int stride, const CaptureOptions& options) {
  if (stride < 2 || stride > 4)
    return "a stroke sample has 2, 3 or 4 numbers (x y [pressure [time]]), got " + std::to_string(stride);
  if (n < 0) n = 0;
  for (int i = 0; i < n; ++i) {
    for (int a = 0; a < stride; ++a) {
      if (!std::isfinite(samples[size_t(i) * stride + a])) {
        static const char* kNames[4] = {"x", "y", "pressure", "time"};
        return "stroke sample " + std::to_string(i) + " has a non-finite " + kNames[a];
      }
    }
  }
  if (!(options.min_spacing >= 0.0) || !std::isfinite(options.min_spacing))
    return "the minimum spacing must be a finite number >= 0";
  auto at = [&](int i) { return Vec2(samples[size_t(i) * stride], samples[size_t(i) * stride + 1]); };
  kept_.clear();
  for (int i = 0; i < n; ++i) {
    if (kept_.empty()) {
      kept_.push_back(i);
      continue;
    }
    const double gap = (at(i) - at(int(kept_.back()))).norm();
    if (gap > options.min_spacing) {
      kept_.push_back(i);
    } else if (i == n - 1 && gap > 0.0) {
      // The stroke ends where the hand stopped: its last sample replaces a too-close last kept one.
      if (kept_.size() > 1)
        kept_.back() = i;
      else
        kept_.push_back(i);
    }
  }
  if (kept_.size() < 2) {
    return "the stroke has fewer than 2 distinct points (" + std::to_string(n) + " samples)";
  }
  const int count = int(kept_.size());
  points_.resize(2 * size_t(count));
  pressure_.resize(size_t(count));
  time_.resize(size_t(count));
  for (int k = 0; k < count; ++k) {
    const int i = int(kept_[size_t(k)]);
    points_[2 * size_t(k)] = samples[size_t(i) * stride];
    points_[2 * size_t(k) + 1] = samples[size_t(i) * stride + 1];
    pressure_[size_t(k)] = stride >= 3 ? samples[size_t(i) * stride + 2] : 1.0;
    time_[size_t(k)] = stride >= 4 ? samples[size_t(i) * stride + 3] : double(i);
  }
  if (!options.resample) return "";

  // §3.2: the same number of control points, evenly spaced by arc length along the sketched curve.
  if (std::string e = curve_.set(points_.data(), count, false, options.parameterization); !e.empty()) return e;
  table_.build(curve_, 0, curve_.segment_count());
  const double total = table_.total();
  std::vector<double>& p = pressure_;
  std::vector<double>& t = time_;
  // kept_ is free now: it holds the old pressure and time while they are interpolated.
  kept_.assign(p.begin(), p.end());
  kept_.insert(kept_.end(), t.begin(), t.end());
  for (int k = 1; k < count - 1; ++k) {
    int s = 0;
    double u = 0.0;
    table_.locate(total * double(k) / double(count - 1), s, u);
    const Vec2 q = curve_.point(s, u);
    points_[2 * size_t(k)] = q.x();
    points_[2 * size_t(k) + 1] = q.y();
    p[size_t(k)] = (1.0 - u) * kept_[size_t(s)] + u * kept_[size_t(s) + 1];
    t[size_t(k)] = (1.0 - u) * kept_[size_t(count + s)] + u * kept_[size_t(count + s) + 1];
  }
  return "";
}

// ---------------------------------------------------------------------------------------------
// Resampler
// ---------------------------------------------------------------------------------------------

std::string Resampler::uniform(const CatmullRom& curve, int count, std::vector<double>& out) {
  const int minimum = curve.closed() ? 3 : 2;
  if (count < minimum || count > kMaxPoints) {
    return "resampling needs between " + std::to_string(minimum) + " and " + std::to_string(kMaxPoints) +
           " points, got " + std::to_string(count);
  }
  if (curve.count() == 0) return "the curve has no control points";
  table_.build(curve, 0, curve.segment_count());
  const double total = table_.total();
  const double step = total / double(curve.closed() ? count : count - 1);
  out.resize(2 * size_t(count));
  at_.resize(size_t(count));
  for (int k = 0; k < count; ++k) {
    int s = 0;
    double u = 0.0;
    if (k == 0) {
      s = 0, u = 0.0;
    } else if (!curve.closed() && k == count - 1) {
      s = curve.segment_count() - 1, u = 1.0;
    } else {
      table_.locate(step * k, s, u);
    }
    // Ends exactly where they were (the pyramid at u = 0, 1 is exact up to rounding; copy instead).
    const Vec2 q = u == 0.0 ? curve.control_point(s) : u == 1.0 ? curve.control_point(s + 1) : curve.point(s, u);
    out[2 * size_t(k)] = q.x();
    out[2 * size_t(k) + 1] = q.y();
    at_[size_t(k)] = s + u;
  }
  return "";
}

std::string Resampler::range(const CatmullRom& curve, int first, int last, int inner, std::vector<double>& out,
                             int& new_first, int& new_last) {
  const int n = curve.count();
  if (first < 0 || first >= n || last < 0 || last >= n) {
    return "the window's ends " + std::to_string(first) + ".." + std::to_string(last) +
           " are out of range (the curve has " + std::to_string(n) + " control points)";
  }
  if (inner < 0 || inner > kMaxPoints)
    return "the number of points inside the window must be in [0, 10000000], got " + std::to_string(inner);
  if (!curve.closed() && first >= last) {
    return "on an open curve the window's first point must come before its last, got " + std::to_string(first) + ".." +
           std::to_string(last);
  }
  const int segments = curve.closed() ? ((last - first) % n + n) % n + (first == last ? n : 0) : last - first;
  table_.build(curve, first, segments);
  const double total = table_.total();
  const std::vector<double>& p = curve.points();
  out.clear();
  auto push_point = [&](int i) {
    out.push_back(p[2 * size_t(i)]);
    out.push_back(p[2 * size_t(i) + 1]);
  };
  auto push_inner = [&]() {
    for (int k = 1; k <= inner; ++k) {
      int s = 0;
      double u = 0.0;
      table_.locate(total * double(k) / double(inner + 1), s, u);
      const Vec2 q = curve.point(first + s, u);
      out.push_back(q.x());
      out.push_back(q.y());
    }
  };
  if (!curve.closed() || first < last) {
    for (int i = 0; i <= first; ++i) push_point(i);
    push_inner();
    for (int i = last; i < n; ++i) push_point(i);
    new_first = first;
    new_last = first + inner + 1;
  } else {
    const int outside = first == last ? 1 : ((first - last) % n + n) % n + 1;
    for (int k = 0; k < outside; ++k) push_point((last + k) % n);
    push_inner();
    new_last = 0;
    new_first = outside - 1;
  }
  const int minimum = curve.closed() ? 3 : 2;
  if (int(out.size() / 2) < minimum) {
    return "the resampled closed curve would have " + std::to_string(out.size() / 2) + " control points (at least 3)";
  }
  return "";
}

}  // namespace splinekit::edit
