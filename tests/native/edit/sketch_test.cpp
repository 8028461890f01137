// Sketch capture and arc-length resampling (§3, §3.2).
#include "edit/sketch.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "common/bezier.h"
#include "test_curves.h"

using namespace splinekit;
using namespace splinekit::edit;

namespace {

// Coefficient of variation of the chords between consecutive points.
double spacing_spread(const std::vector<double>& xy, bool closed) {
  const int n = int(xy.size() / 2);
  std::vector<double> gaps;
  for (int i = 0; i + 1 < n + (closed ? 1 : 0); ++i)
    gaps.push_back((vec2_at(xy.data(), (i + 1) % n) - vec2_at(xy.data(), i)).norm());
  double mean = 0, var = 0;
  for (double g : gaps) mean += g / gaps.size();
  for (double g : gaps) var += (g - mean) * (g - mean) / gaps.size();
  return std::sqrt(var) / mean;
}

CatmullRom make(const std::vector<double>& xy, bool closed) {
  CatmullRom c;
  EXPECT_EQ(c.set(xy.data(), int(xy.size() / 2), closed), "");
  return c;
}

}  // namespace

TEST(ArcLengthTable, MatchesAdaptiveQuadratureAndInverts) {
  const CatmullRom c = make(edit_test::wave(12), false);
  ArcLengthTable t;
  t.build(c, 0, c.segment_count());
  double total = 0;
  for (int s = 0; s < c.segment_count(); ++s) total += c.segment_length(s);
  EXPECT_NEAR(t.total(), total, 1e-6 * total);
  // locate(total/2) lands on a point whose arc length from the start is total/2.
  int s = 0;
  double u = 0;
  t.locate(0.5 * t.total(), s, u);
  double before = 0;
  for (int k = 0; k < s; ++k) before += c.segment_length(k);
  double seg[8];
  c.segment_bezier(s, seg);
  EXPECT_NEAR(before + bezier_arc_length(seg, 0, u, 1e-12), 0.5 * total, 1e-6 * total);
}

TEST(SketchCapture, KeepsSamplesDropsRepeatsAndKeepsPressureAndTime) {
  // x y pressure time; samples 1 and 2 repeat, sample 5 is 0.05 from 4.
  const double s[] = {0, 0, 0.1, 0, 1, 0, 0.2, 10, 1, 0, 0.3, 20, 2, 1, 0.4, 30, 3, 1, 0.5, 40, 3.05, 1, 0.6, 50};
  SketchCapture cap;
  CaptureOptions o;
  ASSERT_EQ(cap.capture(s, 6, 4, o), "");
  EXPECT_EQ(cap.count(), 5);  // the exact repeat is gone
  EXPECT_EQ(cap.pressure()[1], 0.2);
  EXPECT_EQ(cap.time()[3], 40);
  o.min_spacing = 0.1;
  ASSERT_EQ(cap.capture(s, 6, 4, o), "");
  EXPECT_EQ(cap.count(), 4);
  // The stroke's last sample survives (it replaces the too-close one before it).
  EXPECT_EQ(cap.points()[6], 3.05);
  EXPECT_EQ(cap.pressure()[3], 0.6);
  // Without pressure and time: 1 and the sample index.
  const double xy[] = {0, 0, 1, 0, 1, 0};
  ASSERT_EQ(cap.capture(xy, 3, 2, CaptureOptions()), "");
  EXPECT_EQ(cap.count(), 2);
  EXPECT_EQ(cap.pressure()[1], 1.0);
}

TEST(SketchCapture, ResamplingKeepsTheCountAndEvensTheSpacing) {
  // A stroke drawn fast then slow: samples bunch at the end.
  std::vector<double> s;
  for (int i = 0; i < 200; ++i) {
    const double t = std::pow(i / 199.0, 0.4);
    s.insert(s.end(), {100 * t, 20 * std::sin(6 * t), 0.5 + 0.5 * t});
  }
  SketchCapture cap;
  CaptureOptions o;
  ASSERT_EQ(cap.capture(s.data(), 200, 3, o), "");
  const std::vector<double> raw = cap.points();
  o.resample = true;
  ASSERT_EQ(cap.capture(s.data(), 200, 3, o), "");
  EXPECT_EQ(cap.count(), 200);
  EXPECT_GT(spacing_spread(raw, false), 0.5);
  EXPECT_LT(spacing_spread(cap.points(), false), 0.02);
  // Ends stay where the stroke began and ended; pressure is interpolated, still increasing.
  EXPECT_EQ(cap.points()[0], raw[0]);
  EXPECT_EQ(cap.points()[399], raw[399]);
  for (int k = 1; k < 200; ++k) EXPECT_GE(cap.pressure()[size_t(k)], cap.pressure()[size_t(k) - 1]);
}

TEST(SketchCapture, RejectsBadStrokes) {
  SketchCapture cap;
  const double same[] = {1, 1, 1, 1, 1, 1};
  EXPECT_NE(cap.capture(same, 3, 2, CaptureOptions()).find("fewer than 2 distinct points"), std::string::npos);
  const double nan[] = {0, 0, 1, std::nan("")};
  EXPECT_NE(cap.capture(nan, 2, 2, CaptureOptions()).find("stroke sample 1 has a non-finite y"), std::string::npos);
  EXPECT_NE(cap.capture(same, 1, 5, CaptureOptions()).find("2, 3 or 4"), std::string::npos);
}

TEST(Resampler, UniformKeepsTheCountAndEvensTheSpacingOnClosedCurves) {
  const CatmullRom c = make(edit_test::loop(24), true);
  Resampler r;
  std::vector<double> out;
  ASSERT_EQ(r.uniform(c, 24, out), "");
  EXPECT_EQ(out.size(), 48u);
  EXPECT_LT(spacing_spread(out, true), 0.5 * spacing_spread(c.points(), true));
  EXPECT_LT(spacing_spread(out, true), 0.03);
  EXPECT_NE(r.uniform(c, 2, out).find("between 3"), std::string::npos);
}

TEST(Resampler, RangeReplacesOnlyTheWindowInside) {
  const CatmullRom c = make(edit_test::wave(20), false);
  Resampler r;
  std::vector<double> out;
  int nf = 0, nl = 0;
  ASSERT_EQ(r.range(c, 5, 9, 10, out, nf, nl), "");
  EXPECT_EQ(out.size() / 2, 20u - 3u + 10u);
  EXPECT_EQ(nf, 5);
  EXPECT_EQ(nl, 16);
  for (int i = 0; i <= 5; ++i) EXPECT_EQ(vec2_at(out.data(), i), c.control_point(i));
  for (int i = 9; i < 20; ++i) EXPECT_EQ(vec2_at(out.data(), i + 7), c.control_point(i));
  // The new points lie on the old curve, evenly by arc length: spacing within the window even.
  std::vector<double> inside(out.begin() + 2 * 5, out.begin() + 2 * 17);
  EXPECT_LT(spacing_spread(inside, false), 0.05);
  // Lower resolution: no point inside.
  ASSERT_EQ(r.range(c, 5, 9, 0, out, nf, nl), "");
  EXPECT_EQ(out.size() / 2, 17u);
  EXPECT_NE(r.range(c, 9, 5, 3, out, nf, nl).find("must come before"), std::string::npos);
  EXPECT_NE(r.range(c, 5, 20, 3, out, nf, nl).find("out of range"), std::string::npos);
}

TEST(Resampler, RangeWrapsOnAClosedCurve) {
  const CatmullRom c = make(edit_test::loop(12), true);
  Resampler r;
  std::vector<double> out;
  int nf = 0, nl = 0;
  ASSERT_EQ(r.range(c, 10, 2, 5, out, nf, nl), "");
  // Outside: 2..10 (9 points), then 5 new ones; rotated to start at the window's last point.
  EXPECT_EQ(out.size() / 2, 14u);
  EXPECT_EQ(nl, 0);
  EXPECT_EQ(nf, 8);
  EXPECT_EQ(vec2_at(out.data(), 0), c.control_point(2));
  EXPECT_EQ(vec2_at(out.data(), 8), c.control_point(10));
}
