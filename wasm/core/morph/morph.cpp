#include "morph.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/bezier.h"

namespace splinekit::morph {

namespace {

void drawing_box(const SplineSet& s, double* box) {
  box[0] = box[1] = std::numeric_limits<double>::infinity();
  box[2] = box[3] = -std::numeric_limits<double>::infinity();
  double b[4];
  for (int i = 0; i < s.spline_count(); ++i) {
    spline_bounds(s.spline_points(i), s.count[size_t(i)], s.closed[size_t(i)] != 0, b);
    box[0] = std::min(box[0], b[0]);
    box[1] = std::min(box[1], b[1]);
    box[2] = std::max(box[2], b[2]);
    box[3] = std::max(box[3], b[3]);
  }
}

// Index of the anchor of `c` nearest p, and its squared distance.
int nearest_anchor(const KnotChain& c, const Vec2& p, double* d2) {
  int best = 0;
  *d2 = std::numeric_limits<double>::infinity();
  for (int a = 0; a < c.anchors(); ++a) {
    const double d = (vec2_at(c.points.data(), 3 * a) - p).squaredNorm();
    if (d < *d2) *d2 = d, best = a;
  }
  return best;
}

// Centroid and RMS radius of a drawing's curves (sampled 8 times per segment): the frame the
// travel work compares positions in. A rotation, move or scale of the drawing moves it along.
Frame frame_of(const SplineSet& s) {
  double sx = 0, sy = 0, sxx = 0;
  int count = 0;
  double seg[8];
  for (int i = 0; i < s.spline_count(); ++i) {
    const bool closed = s.closed[size_t(i)] != 0;
    for (int k = 0; k < spline_segment_count(s.count[size_t(i)], closed); ++k) {
      spline_segment(s.spline_points(i), s.count[size_t(i)], closed, k, seg);
      for (int u = 0; u < 8; ++u) {
        const Vec2 p = bezier_point(seg, u / 8.0);
        sx += p.x();
        sy += p.y();
        sxx += p.squaredNorm();
        ++count;
      }
    }
  }
  Frame f;
  f.cx = sx / count;
  f.cy = sy / count;
  f.radius = std::sqrt(std::max(sxx / count - f.cx * f.cx - f.cy * f.cy, 0.0));
  if (!(f.radius > 0)) f.radius = 1;
  return f;
}

}  // namespace

std::string Morph::setup(const SplineSet& a_in, const SplineSet& b_in, const MorphOptions& options,
                         const std::vector<MorphPin>& pins) {
  for (const auto* s : {&a_in, &b_in}) {
    const char* name = s == &a_in ? "the first shape" : "the second shape";
    if (std::string e = validate(*s); !e.empty()) return std::string(name) + ": " + e;
    if (s->spline_count() == 0) return std::string(name) + " has no contour";
    if (total_segments(*s) == 0) return std::string(name) + " has no curve segment";
  }
  // Contours of zero length (a lone point, "M x y Z", a segment whose points coincide) draw nothing
  // and have no shape to blend: they are left out, and the indices reported stay the given ones.
  SplineSet a, b;
  std::vector<int> index_a, index_b;
  for (int which = 0; which < 2; ++which) {  // by position: a and b may be the same set
    const SplineSet* s = which == 0 ? &a_in : &b_in;
    SplineSet& out = which == 0 ? a : b;
    std::vector<int>& index = which == 0 ? index_a : index_b;
    double box[4];
    drawing_box(*s, box);
    const double size = std::hypot(box[2] - box[0], box[3] - box[1]);
    double seg[8];
    for (int i = 0; i < s->spline_count(); ++i) {
      const bool closed = s->closed[size_t(i)] != 0;
      double length = 0;
      for (int k = 0; k < spline_segment_count(s->count[size_t(i)], closed); ++k) {
        spline_segment(s->spline_points(i), s->count[size_t(i)], closed, k, seg);
        length += bezier_arc_length(seg, 0.0, 1.0, 1e-12 * size);
      }
      if (!(length > 1e-9 * size)) continue;
      index.push_back(i);
      out.start.push_back(int32_t(out.points.size() / 2));
      out.count.push_back(s->count[size_t(i)]);
      out.closed.push_back(s->closed[size_t(i)]);
      out.points.insert(out.points.end(), s->spline_points(i), s->spline_points(i) + 2 * size_t(s->count[size_t(i)]));
    }
    if (out.spline_count() == 0)
      return std::string(which == 0 ? "the first shape" : "the second shape") + " has no contour of nonzero length";
  }
  if (std::string e = validate(options.work); !e.empty()) return e;
  if (!std::isfinite(options.segment_limit) || options.segment_limit < 0)
    return "the segment limit must be a finite number >= 0";
  if (!std::isfinite(options.length_unit) || options.length_unit <= 0)
    return "the length unit must be a finite number > 0";
  if (!std::isfinite(options.continuity_tolerance) || options.continuity_tolerance < 0)
    return "the continuity tolerance must be a finite number >= 0";
  for (size_t k = 0; k < pins.size(); ++k) {
    const MorphPin& p = pins[k];
    if (!std::isfinite(p.ax) || !std::isfinite(p.ay) || !std::isfinite(p.bx) || !std::isfinite(p.by))
      return "pin " + std::to_string(k) + " has a non-finite coordinate";
  }
  double box_a[4], box_b[4];
  drawing_box(a, box_a);
  drawing_box(b, box_b);
  const double size_a = std::hypot(box_a[2] - box_a[0], box_a[3] - box_a[1]);
  const double size_b = std::hypot(box_b[2] - box_b[0], box_b[3] - box_b[1]);
  if (!(size_a > 0)) return "the first shape has zero size (all its points coincide)";
  if (!(size_b > 0)) return "the second shape has zero size (all its points coincide)";
  // Lengths in the work terms are measured in `length_unit`s of the mean total length of the two
  // drawings (a rotation changes a box's size, not a length).
  double total_length[2] = {0, 0};

  // 1. Chains.
  auto chains_of = [&](const SplineSet& s, double size, std::vector<KnotChain>& out) -> std::string {
    double& drawing_length = total_length[&s == &a ? 0 : 1];
    out.resize(size_t(s.spline_count()));
    for (int i = 0; i < s.spline_count(); ++i) {
      const bool closed = s.closed[size_t(i)] != 0;
      // §6 limits segments to ~5% of the contour's box width; the width is taken as the diameter
      // of a circle of the contour's length (perimeter / π), which a rotation does not change.
      double length = 0, seg[8];
      for (int k = 0; k < spline_segment_count(s.count[size_t(i)], closed); ++k) {
        spline_segment(s.spline_points(i), s.count[size_t(i)], closed, k, seg);
        length += bezier_arc_length(seg, 0.0, 1.0, 1e-9 * size);
      }
      drawing_length += length;
      ChainOptions co;
      co.length_tolerance = options.continuity_tolerance * size;
      co.max_length = options.segment_limit * length / kPi;
      if (std::string e = chain_from_bezier(s.spline_points(i), s.count[size_t(i)], closed, co, out[size_t(i)]);
          !e.empty())
        return "contour " + std::to_string(i) + ": " + e;
    }
    return "";
  };
  std::vector<KnotChain> ca, cb;
  if (std::string e = chains_of(a, size_a, ca); !e.empty()) return "the first shape, " + e;
  if (std::string e = chains_of(b, size_b, cb); !e.empty()) return "the second shape, " + e;
  const double reference = options.length_unit * 0.5 * (total_length[0] + total_length[1]);
  const Frame frame_a = frame_of(a), frame_b = frame_of(b);

  // 2. Pairing, pulled by pins.
  const std::vector<ContourShape> da = describe_contours(a), db = describe_contours(b);
  struct Snapped {
    int ca, aa, cb, ab;
  };
  std::vector<Snapped> snapped;
  for (const MorphPin& p : pins) {
    Snapped s{0, 0, 0, 0};
    double best = std::numeric_limits<double>::infinity(), d2;
    for (int i = 0; i < int(ca.size()); ++i) {
      const int an = nearest_anchor(ca[size_t(i)], Vec2(p.ax, p.ay), &d2);
      if (d2 < best) best = d2, s.ca = i, s.aa = an;
    }
    best = std::numeric_limits<double>::infinity();
    for (int j = 0; j < int(cb.size()); ++j) {
      const int an = nearest_anchor(cb[size_t(j)], Vec2(p.bx, p.by), &d2);
      if (d2 < best) best = d2, s.cb = j, s.ab = an;
    }
    snapped.push_back(s);
  }
  std::vector<double> bonus(ca.size() * cb.size(), 0.0);
  for (const Snapped& s : snapped) bonus[size_t(s.ca) * cb.size() + size_t(s.cb)] += 10.0;
  std::vector<int> partner_a, partner_b;
  pair_contours(da, box_a, db, box_b, bonus, partner_a, partner_b);

  // 3–5. Correspondence and blend per pair (A's order), then contours that grow.
  std::vector<ContourBlend> blends;
  std::vector<BlendedContour> info;
  double total = 0;
  for (int i = 0; i < int(ca.size()); ++i) {
    BlendedContour bc;
    bc.contour_a = i;
    bc.contour_b = partner_a[size_t(i)];
    KnotChain chain_a = ca[size_t(i)];
    ContourBlend blend;
    if (bc.contour_b < 0) {
      const Vec2 p = partner_point(da[size_t(i)], da, box_a, db, box_b, partner_a);
      const KnotChain target = point_chain(p.x(), p.y(), chain_a.segments(), chain_a.closed);
      const std::vector<Move> moves(size_t(chain_a.segments()), Move::kBoth);
      const ChainMeasure m = measure(chain_a, reference, frame_a);
      const double q[2] = {(p.x() - frame_b.cx) / frame_b.radius, (p.y() - frame_b.cy) / frame_b.radius};
      for (int k = 0; k < chain_a.segments(); ++k)
        bc.work += stretching_work(m.length[size_t(k)], 0, options.work) +
                   bending_work(m.bending[size_t(k)], 0, m.length[size_t(k)], 0, options.work) +
                   travel_work(m.length[size_t(k)], 0, &m.middle[2 * size_t(k)], q, options.work);
      for (double th : m.kink) bc.work += kinking_work(th, 0, options.work);
      blend.build(chain_a, target, moves);
    } else {
      const KnotChain& chain_b = cb[size_t(bc.contour_b)];
      std::vector<AnchorPin> anchor_pins;
      for (const Snapped& s : snapped)
        if (s.ca == i && s.cb == bc.contour_b) anchor_pins.push_back({s.aa, s.ab});
      bc.pins = int(anchor_pins.size());
      if (chain_a.closed && !anchor_pins.empty()) {
        // A starts at the first pin, so every start of B the pins allow is a start of the search.
        const int first = anchor_pins[0].a;
        chain_a = rotated(chain_a, first);
        for (AnchorPin& p : anchor_pins)
          p.a = ((p.a - first) % chain_a.anchors() + chain_a.anchors()) % chain_a.anchors();
      }
      const KnotChain back = reversed(chain_b);
      const ChainMeasure ma = measure(chain_a, reference, frame_a), mf = measure(chain_b, reference, frame_b),
                         mb = measure(back, reference, frame_b);
      int directions = CorrespondenceSearch::kBoth;
      if (options.direction == Direction::kForward) directions = CorrespondenceSearch::kForward;
      if (options.direction == Direction::kWinding && chain_a.closed) {
        const bool same = (da[size_t(i)].area >= 0) == (db[size_t(bc.contour_b)].area >= 0);
        directions = same ? CorrespondenceSearch::kForward : CorrespondenceSearch::kBackward;
      }
      const Correspondence c = search_.search(ma, mf, mb, chain_a.closed, anchor_pins, options.work, directions);
      if (!std::isfinite(c.work)) {
        return "the pins on contour " + std::to_string(i) +
               " of the first shape cross each other (no correspondence keeps them all)";
      }
      bc.work = c.work;
      bc.start = c.start;
      bc.reversed = c.reversed;
      const KnotChain& directed = c.reversed ? back : chain_b;
      blend.build(chain_a, chain_a.closed ? rotated(directed, c.start) : directed, c.moves);
    }
    total += bc.work;
    blends.push_back(std::move(blend));
    info.push_back(bc);
  }
  for (int j = 0; j < int(cb.size()); ++j) {
    if (partner_b[size_t(j)] >= 0) continue;
    BlendedContour bc;
    bc.contour_b = j;
    const KnotChain& chain_b = cb[size_t(j)];
    const Vec2 p = partner_point(db[size_t(j)], db, box_b, da, box_a, partner_b);
    const KnotChain source = point_chain(p.x(), p.y(), chain_b.segments(), chain_b.closed);
    const ChainMeasure m = measure(chain_b, reference, frame_b);
    const double q[2] = {(p.x() - frame_a.cx) / frame_a.radius, (p.y() - frame_a.cy) / frame_a.radius};
    for (int k = 0; k < chain_b.segments(); ++k)
      bc.work += stretching_work(0, m.length[size_t(k)], options.work) +
                 bending_work(0, m.bending[size_t(k)], 0, m.length[size_t(k)], options.work) +
                 travel_work(0, m.length[size_t(k)], q, &m.middle[2 * size_t(k)], options.work);
    for (double th : m.kink) bc.work += kinking_work(0, th, options.work);
    ContourBlend blend;
    blend.build(source, chain_b, std::vector<Move>(size_t(chain_b.segments()), Move::kBoth));
    total += bc.work;
    blends.push_back(std::move(blend));
    info.push_back(bc);
  }

  for (BlendedContour& bc : info) {
    if (bc.contour_a >= 0) bc.contour_a = index_a[size_t(bc.contour_a)];
    if (bc.contour_b >= 0) bc.contour_b = index_b[size_t(bc.contour_b)];
  }
  blends_ = std::move(blends);
  info_ = std::move(info);
  work_ = total;
  start_.clear();
  count_.clear();
  closed_.clear();
  coupled_.clear();
  total_points_ = 0;
  for (const ContourBlend& bl : blends_) {
    start_.push_back(total_points_);
    count_.push_back(bl.point_count());
    closed_.push_back(bl.closed() ? 1 : 0);
    total_points_ += bl.point_count();
    coupled_.insert(coupled_.end(), bl.coupled().begin(), bl.coupled().end());
  }
  return "";
}

void Morph::evaluate(double t, Interpolation mode, double* out) {
  for (size_t c = 0; c < blends_.size(); ++c) blends_[c].evaluate(t, mode, out + 2 * size_t(start_[c]));
}

}  // namespace splinekit::morph
