// The straightening's steps one at a time (straighten.h), each against what a hand-made mesh says
// it must give: the semi-star flip takes a vertex's other side (or freezes a saddle), a zipper takes
// in exactly the vertices that still block, a chord's faces are those the straight line crosses,
// apply lays the new strip as a fresh layout would, and a pass is what the whole loop repeats.
#include "surface/straighten.h"
#include "surface/geodesic.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace splinekit::surface {
namespace {

using testing::Arrays;

int vertex_near(const TriMesh& mesh, const Vec3& p) {
  for (size_t v = 0; v < mesh.positions.size(); ++v)
    if ((mesh.positions[v] - p).norm() < 1e-9) return static_cast<int>(v);
  ADD_FAILURE() << "no vertex at " << p.transpose();
  return -1;
}

MeshPoint centroid(int face) { return {face, Vec2(1.0 / 3, 1.0 / 3)}; }

// Consecutive faces share an edge and no face comes twice.
void expect_strip(const TriMesh& mesh, const std::vector<int>& strip) {
  for (size_t i = 0; i + 1 < strip.size(); ++i)
    EXPECT_GE(edge_to(mesh, strip[i], strip[i + 1]), 0) << "faces " << i << ", " << i + 1;
  std::vector<int> sorted = strip;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end()) << "a face twice";
}

// A layout `u` of `strip` that matches a fresh unfolding of it (the first face is laid alike).
void expect_fresh_layout(const TriMesh& mesh, const std::vector<int>& strip, const UnfoldedStrip& u) {
  UnfoldedStrip fresh;
  unfold_strip(mesh, strip, fresh);
  ASSERT_EQ(u.faces, strip);
  ASSERT_EQ(u.corners.size(), fresh.corners.size());
  for (size_t i = 0; i < strip.size(); ++i)
    for (int k = 0; k < 3; ++k) EXPECT_NEAR((u.corners[i][k] - fresh.corners[i][k]).norm(), 0, 1e-12) << "face " << i;
  for (size_t i = 0; i + 1 < strip.size(); ++i) {
    EXPECT_EQ(u.portals[i].left_vertex, fresh.portals[i].left_vertex);
    EXPECT_EQ(u.portals[i].right_vertex, fresh.portals[i].right_vertex);
  }
}

// `flip` made on the strip being straightened (apply): the new strip is a strip, laid out as a
// fresh layout would lay it (`out`: its faces). Returns its funnel path's length, `after` its apices.
double made_length(const TriMesh& mesh, Straightener& s, const Flip& flip, std::vector<Apex>& after,
                   std::vector<int>* out = nullptr) {
  std::vector<int> strip;
  UnfoldedStrip u;
  Splice splice;
  s.apply({&flip}, strip, u, splice);
  expect_strip(mesh, strip);
  expect_fresh_layout(mesh, strip, u);
  if (out) *out = strip;
  std::vector<Apex> raw;
  return s.shorten(u, raw, after, splice.path ? &splice : nullptr);
}

// The strip of the straight shortest paths through `via` on a flat mesh (consecutive pieces meet
// inside a face), loops cut: the kind of strip phase (i) hands over, bent where `via` bends.
std::vector<int> strip_through(const TriMesh& mesh, const std::vector<MeshPoint>& via) {
  GeodesicSolver solver(mesh);
  std::vector<int> strip;
  for (size_t i = 0; i + 1 < via.size(); ++i) {
    GeodesicPath piece;
    EXPECT_TRUE(solver.shortest_path(via[i], via[i + 1], piece));
    if (!strip.empty()) {
      EXPECT_EQ(strip.back(), piece.strip.front());
    }
    strip.insert(strip.end(), piece.strip.begin() + (strip.empty() ? 0 : 1), piece.strip.end());
  }
  std::vector<int> marks(mesh.triangles.size(), -1);
  remove_loops(strip, marks);
  return strip;
}

MeshPoint at_xy(const TriMesh& mesh, double x, double y) { return testing::point_at(mesh, Vec3(x, y, 0)); }

// The faces around vertex v, in order (empty when v's fan is open: on a boundary).
std::vector<int> closed_fan(const TriMesh& mesh, int v) {
  std::vector<int> fan;
  bool closed;
  vertex_fan(mesh, v, fan, closed);
  return closed ? fan : std::vector<int>{};
}

// The semi-star flip of apex j of the strip being straightened, and the room its chord may take
// (from the faces around the apex before to those around the apex after), as a pass finds them.
void semi_star_and_room(Straightener& s, size_t j, ChordRoom& room, Flip& flip) {
  const std::vector<Apex>& apices = s.apices();
  const int n = static_cast<int>(s.strip().size());
  room = ChordRoom{0, n - 1, n - 1};
  int unused;
  if (apices[j - 1].vertex >= 0) {
    ASSERT_TRUE(s.run_of(apices[j - 1].vertex, apices[j - 1].portal, room.p_first, unused));
  }
  if (apices[j + 1].vertex >= 0) {
    ASSERT_TRUE(s.run_of(apices[j + 1].vertex, apices[j + 1].portal, room.q_first, room.q_last));
  }
  int first, last;
  ASSERT_TRUE(s.run_of(apices[j].vertex, apices[j].portal, first, last));
  ASSERT_TRUE(s.flip(j, turn_at(apices, j), first, last, flip));
}

// ---- Semi-star ----------------------------------------------------------------------------------

TEST(StraightenerFlip, TakesTheOtherSemiStarOfAFlatVertex) {
  // The 8 faces around the middle vertex of a 4 x 4 grid; the strip holds 6 of them (270°), so the
  // path between the centroids of its ends bends at the vertex. Its other semi-star is the other 2.
  const TriMesh mesh = testing::build(testing::planar_grid(4, 1, 0));
  const int v = vertex_near(mesh, {0.5, 0.5, 0});
  const std::vector<int> fan = closed_fan(mesh, v);
  ASSERT_EQ(fan.size(), 8u);
  const std::vector<int> strip(fan.begin(), fan.begin() + 6);
  const MeshPoint a = centroid(strip.front()), b = centroid(strip.back());
  const Vec3 pa = eval_position(mesh, a), pb = eval_position(mesh, b), pv = mesh.positions[v];

  std::vector<int> marks(mesh.triangles.size(), -1);
  Straightener s(mesh, marks);
  s.begin(a, b, strip);
  ASSERT_EQ(s.apices().size(), 3u);
  EXPECT_EQ(s.apices()[1].vertex, v);
  EXPECT_NEAR(s.length(), (pv - pa).norm() + (pb - pv).norm(), 1e-12);
  const double turn = turn_at(s.apices(), 1);
  EXPECT_NEAR(turn, std::acos((pv - pa).normalized().dot((pb - pv).normalized())), 1e-9);

  int first, last;
  ASSERT_TRUE(s.run_of(v, s.apices()[1].portal, first, last));
  EXPECT_EQ(first, 0);
  EXPECT_EQ(last, 5);
  Flip flip;
  ASSERT_TRUE(s.flip(1, turn, first, last, flip));
  EXPECT_EQ(flip.vertex, v);
  EXPECT_EQ(flip.other, (std::vector<int>{fan[7], fan[6]}));  // from strip[first] the other way round
  EXPECT_FALSE(flip.chain || flip.chord);

  // Made, the strip is the 4 faces on the other side; on a plane its funnel path is the segment.
  std::vector<int> out;
  std::vector<Apex> apices;
  EXPECT_NEAR(made_length(mesh, s, flip, apices, &out), (pb - pa).norm(), 1e-12);
  EXPECT_EQ(out, (std::vector<int>{fan[0], fan[7], fan[6], fan[5]}));
  EXPECT_EQ(apices.size(), 2u);
}

// A saddle: a vertex whose 6 faces alternate up and down, so that its angle sum exceeds 2π.
Arrays saddle() {
  Arrays a;
  a.positions = {0, 0, 0};
  for (int i = 0; i < 6; ++i)
    a.positions.insert(a.positions.end(), {std::cos(kPi * i / 3), std::sin(kPi * i / 3), i % 2 ? -0.8 : 0.8});
  for (int i = 0; i < 6; ++i) a.triangles.insert(a.triangles.end(), {0, 1 + i, 1 + (i + 1) % 6});
  return a;
}

TEST(StraightenerFlip, FreezesASaddleVertexThePathGoesStraightThrough) {
  const TriMesh mesh = testing::build(saddle());
  const int v = vertex_near(mesh, Vec3::Zero());
  const std::vector<int> fan = closed_fan(mesh, v);
  ASSERT_EQ(fan.size(), 6u);
  // The angle sum, and the strip's half: 3 faces around v between the centroids of the outer two.
  double theta = 0;
  for (int f : fan) theta += corner_angle(mesh, f, v);
  const Vec3 r0(1, 0, 0.8), r1(0.5, std::sqrt(0.75), -0.8);
  EXPECT_NEAR(theta, 6 * std::acos(r0.dot(r1) / r0.squaredNorm()), 1e-12);
  EXPECT_GT(theta, 2 * kPi);
  const std::vector<int> strip = {fan[0], fan[1], fan[2]};
  const MeshPoint a = centroid(strip.front()), b = centroid(strip.back());
  const Vec3 pa = eval_position(mesh, a), pb = eval_position(mesh, b), pv = mesh.positions[v];

  std::vector<int> marks(mesh.triangles.size(), -1);
  Straightener s(mesh, marks);
  s.begin(a, b, strip);
  ASSERT_EQ(s.apices().size(), 3u);
  ASSERT_EQ(s.apices()[1].vertex, v);
  const double turn = turn_at(s.apices(), 1);
  // The other side spans θ − (π + turn) ≥ π: the path through v is locally shortest.
  ASSERT_GE(theta - kPi - turn, kPi);
  int first, last;
  ASSERT_TRUE(s.run_of(v, s.apices()[1].portal, first, last));
  Flip flip;
  EXPECT_FALSE(s.flip(1, turn, first, last, flip));
  EXPECT_EQ(flip.other, (std::vector<int>{fan[5], fan[4], fan[3]}));

  GeodesicPath path;
  PathStats stats;
  std::vector<int> in = strip;
  s.straighten(a, b, in, path, &stats);
  EXPECT_EQ(stats.frozen_vertices, 1);
  EXPECT_EQ(stats.accepted_flips, 0);
  EXPECT_EQ(path.strip, strip);
  EXPECT_NEAR(path_length(mesh, path), (pv - pa).norm() + (pb - pv).norm(), 1e-12);
}

// ---- Zipper -------------------------------------------------------------------------------------

TEST(StraightenerZipper, TakesInExactlyTheVerticesThatStillBlock) {
  // A strip that runs just under row 12 of a 24 x 24 grid between ends just above it: the path
  // bends down onto the row, runs along it and up again.
  const TriMesh mesh = testing::build(testing::planar_grid(24, 1, 0));
  const double cell = 1.0 / 24, row = 12 * cell;
  const std::vector<int> strip =
      strip_through(mesh, {at_xy(mesh, 0.1, row + 0.3 * cell), at_xy(mesh, 0.15, row - 0.3 * cell),
                           at_xy(mesh, 0.85, row - 0.3 * cell), at_xy(mesh, 0.9, row + 0.3 * cell)});
  std::vector<int> marks(mesh.triangles.size(), -1);
  Straightener s(mesh, marks);
  s.begin(at_xy(mesh, 0.1, row + 0.3 * cell), at_xy(mesh, 0.9, row + 0.3 * cell), strip);
  const std::vector<Apex>& apices = s.apices();
  ASSERT_GE(apices.size(), 3u);
  const int v = apices[1].vertex;
  ASSERT_GE(v, 0);
  EXPECT_NEAR(mesh.positions[v].y(), row, 1e-12);

  // Independently: the row vertices on v's side of the strip, strictly between apex 0 and apex 2
  // (along x), that lie on v's side of the line between those apices, in strip order (left to right).
  const Portal& own = s.unfolded().portals[apices[1].portal];
  const bool v_left = own.left_vertex == v;
  std::vector<int> boundary;  // the strip's vertices on v's side
  for (const Portal& portal : s.unfolded().portals)
    boundary.push_back(v_left ? portal.left_vertex : portal.right_vertex);
  auto on_boundary = [&](int w) { return std::find(boundary.begin(), boundary.end(), w) != boundary.end(); };
  const MeshPoint a = at_xy(mesh, 0.1, row + 0.3 * cell), b = at_xy(mesh, 0.9, row + 0.3 * cell);
  auto position_of = [&](const Apex& x, const MeshPoint& end) {
    return x.vertex >= 0 ? mesh.positions[x.vertex] : eval_position(mesh, end);
  };
  const Vec3 from = position_of(apices[0], a), to = position_of(apices[2], b), pv = mesh.positions[v];
  auto side = [&](const Vec3& w) { return orient(from.head<2>(), to.head<2>(), w.head<2>()); };
  std::vector<std::pair<double, int>> row_vertices;
  for (size_t w = 0; w < mesh.positions.size(); ++w) {
    const Vec3& x = mesh.positions[w];
    if (std::abs(x.y() - row) < 1e-12 && x.x() > from.x() && x.x() < to.x() && side(x) * side(pv) > 0 &&
        on_boundary(static_cast<int>(w)))
      row_vertices.emplace_back(x.x(), static_cast<int>(w));
  }
  std::sort(row_vertices.begin(), row_vertices.end());
  std::vector<int> expected;
  for (const auto& [x, w] : row_vertices) expected.push_back(w);
  ASSERT_GT(expected.size(), 2u);

  int first, last;
  ASSERT_TRUE(s.run_of(v, apices[1].portal, first, last));
  Flip flip;
  ASSERT_TRUE(s.flip(1, turn_at(apices, 1), first, last, flip));
  const size_t semi_star = flip.other.size();
  s.zipper(1, flip);
  EXPECT_TRUE(flip.chain);
  EXPECT_EQ(s.zipper_pivots(), expected);

  EXPECT_GT(flip.other.size(), semi_star);
  // Made, the path no longer touches any of them and is shorter.
  std::vector<Apex> after;
  EXPECT_LT(made_length(mesh, s, flip, after), s.length() - 1e-6);
  for (const Apex& x : after)
    EXPECT_EQ(std::find(expected.begin(), expected.end(), x.vertex), expected.end()) << x.vertex;
}

// ---- Chord --------------------------------------------------------------------------------------

// The faces the open segment a -> b of the plane z = 0 crosses, in the order it enters them.
std::vector<int> faces_crossed(const TriMesh& mesh, const Vec2& a, const Vec2& b) {
  std::vector<std::pair<double, int>> hit;
  const Vec2 d = b - a;
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    Vec2 c[3];
    for (int k = 0; k < 3; ++k) c[k] = mesh.positions[mesh.triangles[f][k]].head<2>();
    if (orient(c[0], c[1], c[2]) < 0) std::swap(c[1], c[2]);
    double t0 = 0, t1 = 1;  // clipped against each edge's inner half-plane
    for (int k = 0; k < 3; ++k) {
      const Vec2 &p = c[k], &q = c[(k + 1) % 3];
      const double at0 = orient(p, q, a), slope = cross(q - p, d);  // inside: at0 + t * slope > 0
      if (slope == 0) {
        if (at0 <= 0) t1 = -1;
      } else if (slope > 0) {
        t0 = std::max(t0, -at0 / slope);
      } else {
        t1 = std::min(t1, -at0 / slope);
      }
    }
    if (t1 - t0 > 1e-9) hit.emplace_back(t0, static_cast<int>(f));
  }
  std::sort(hit.begin(), hit.end());
  std::vector<int> out;
  for (const auto& [t, f] : hit) out.push_back(f);
  return out;
}

TEST(StraightenerChord, LaysTheFacesTheStraightLineCrosses) {
  // A strip that dips far below the segment between its ends; the chord at one of its bends
  // replaces the strip between the neighbouring apices by the faces along the line between them.
  const TriMesh mesh = testing::build(testing::planar_grid(24, 1, 0));
  const MeshPoint a = at_xy(mesh, 0.1, 0.8), b = at_xy(mesh, 0.9, 0.8);
  const std::vector<int> strip = strip_through(mesh, {a, at_xy(mesh, 0.51, 0.13), b});
  std::vector<int> marks(mesh.triangles.size(), -1);
  Straightener s(mesh, marks);
  s.begin(a, b, strip);
  const std::vector<Apex>& apices = s.apices();
  ASSERT_GE(apices.size(), 3u);
  // (the apex whose neighbours lie farthest apart: the longest chord)
  auto span = [&](size_t i) { return (apices[i + 1].pos - apices[i - 1].pos).norm(); };
  size_t j = 1;
  for (size_t i = 2; i + 1 < apices.size(); ++i)
    if (span(i) > span(j)) j = i;
  ChordRoom room;
  Flip flip;
  ASSERT_NO_FATAL_FAILURE(semi_star_and_room(s, j, room, flip));
  ASSERT_TRUE(s.chord(j, room, flip));
  EXPECT_TRUE(flip.chord);
  ASSERT_EQ(flip.laid.size(), flip.other.size());

  // The line in space (the mesh is the plane z = 0): from apex j-1 to apex j+1.
  auto place = [&](const Apex& x, const MeshPoint& end) -> Vec2 {
    const Vec3 at = x.vertex >= 0 ? mesh.positions[x.vertex] : eval_position(mesh, end);
    return at.head<2>();
  };
  const Vec2 p = place(apices[j - 1], a), q = place(apices[j + 1], b);
  // Its faces but those around p and q (the chord turns around them to the strip) and those the
  // strip keeps at either end: the chord's new faces, in order.
  std::vector<int> expected;
  for (int f : faces_crossed(mesh, p, q)) {
    if ((apices[j - 1].vertex >= 0 && contains_vertex(mesh, f, apices[j - 1].vertex)) ||
        (apices[j + 1].vertex >= 0 && contains_vertex(mesh, f, apices[j + 1].vertex)))
      continue;
    if (f == strip[flip.first] || f == strip[flip.last]) continue;
    expected.push_back(f);
  }
  std::vector<int> along;
  for (int f : flip.other)
    if (!(apices[j - 1].vertex >= 0 && contains_vertex(mesh, f, apices[j - 1].vertex)) &&
        !(apices[j + 1].vertex >= 0 && contains_vertex(mesh, f, apices[j + 1].vertex)))
      along.push_back(f);
  ASSERT_GT(expected.size(), 10u);
  EXPECT_EQ(along, expected);
  // Where the walk laid them is where the strip's layout puts them: made, the layout is a fresh one.
  // The path can run straight from p to q now: it is shorter by at least what the bend at v cost.
  const double bend = (apices[j].pos - apices[j - 1].pos).norm() + (apices[j + 1].pos - apices[j].pos).norm() -
                      (apices[j + 1].pos - apices[j - 1].pos).norm();
  ASSERT_GT(bend, 1e-5);
  std::vector<Apex> after;
  EXPECT_LE(made_length(mesh, s, flip, after), s.length() - bend + 1e-12);
}

TEST(StraightenerChord, AWalkThatFailedBetweenTheSameApicesIsNotWalkedAgain) {
  // A plane with a square hole above the bend of a V-shaped strip: the straight line between the
  // bend's neighbouring apices runs into the hole, so the chord fails (its walk meets the boundary),
  // and it would fail the same way in every pass while those apices stay.
  testing::Arrays grid = testing::planar_grid(24, 1, 0);
  std::vector<int> kept;
  for (size_t t = 0; t < grid.triangles.size(); t += 3) {
    Vec3 c = Vec3::Zero();
    for (int k = 0; k < 3; ++k) c += Vec3(grid.positions.data() + 3 * grid.triangles[t + k]) / 3;
    if (c.x() > 0.42 && c.x() < 0.58 && c.y() > 0.35 && c.y() < 0.95) continue;
    kept.insert(kept.end(), grid.triangles.begin() + t, grid.triangles.begin() + t + 3);
  }
  grid.triangles = kept;
  const TriMesh mesh = testing::build(grid);
  const MeshPoint a = at_xy(mesh, 0.15, 0.85), b = at_xy(mesh, 0.85, 0.85);
  const std::vector<int> strip = strip_through(mesh, {a, at_xy(mesh, 0.51, 0.06), b});
  std::vector<int> marks(mesh.triangles.size(), -1);
  Straightener s(mesh, marks);
  s.begin(a, b, strip);
  const std::vector<Apex>& apices = s.apices();
  // The bend whose neighbouring apices' line crosses the hole (the plane: the layout is space's).
  auto place = [&](const Apex& x, const MeshPoint& end) -> Vec2 {
    return (x.vertex >= 0 ? mesh.positions[x.vertex] : eval_position(mesh, end)).head<2>();
  };
  size_t j = 0;
  for (size_t i = 1; i + 1 < apices.size() && j == 0; ++i) {
    const Vec2 p = place(apices[i - 1], a), q = place(apices[i + 1], b);
    for (double t = 0; t <= 1; t += 0.01) {
      const Vec2 x = p + t * (q - p);
      if (x.x() > 0.45 && x.x() < 0.55 && x.y() > 0.4 && x.y() < 0.9) j = i;
    }
  }
  ASSERT_GT(j, 0u) << "no bend whose chord crosses the hole";
  ChordRoom room;
  Flip flip;
  ASSERT_NO_FATAL_FAILURE(semi_star_and_room(s, j, room, flip));
  const Flip semi_star = flip;
  // The chord itself walks towards the hole and fails, leaving the semi-star as it was.
  int walked = s.walked();
  EXPECT_FALSE(s.chord(j, room, flip));
  EXPECT_GT(s.walked(), walked + 3);
  EXPECT_EQ(flip.other, semi_star.other);
  // The pass's way to it: the first time it walks (and fails) alike, then it is not walked again.
  walked = s.walked();
  EXPECT_FALSE(s.walk_chord(j, room, flip));
  const int first_walk = s.walked() - walked;
  EXPECT_GT(first_walk, 3);
  walked = s.walked();
  EXPECT_FALSE(s.walk_chord(j, room, flip));
  EXPECT_EQ(s.walked(), walked);
  EXPECT_EQ(flip.other, semi_star.other);
  EXPECT_FALSE(flip.chord);
  // begin() forgets it with the path's other per-vertex state: the next path walks it again.
  s.begin(a, b, strip);
  walked = s.walked();
  EXPECT_FALSE(s.walk_chord(j, room, flip));
  EXPECT_EQ(s.walked() - walked, first_walk);
}

// ---- Span ---------------------------------------------------------------------------------------

// On the unit square's grid `mesh`: a strip from a to b through two dips below the segment between
// them, whose funnel path bends at several vertices between the ends.
std::vector<int> two_dips(const TriMesh& mesh, MeshPoint& a, MeshPoint& b) {
  a = at_xy(mesh, 0.1, 0.7), b = at_xy(mesh, 0.9, 0.7);
  return strip_through(mesh, {a, at_xy(mesh, 0.3, 0.21), at_xy(mesh, 0.52, 0.49), at_xy(mesh, 0.71, 0.13), b});
}

TEST(StraightenerSpan, CrossesEveryBendBetweenItsEndsAtOnce) {
  // The span from the start to the end (chord(0, last)) takes the faces the segment a -> b crosses
  // (the flat plane: layout and space agree) in place of the strip's between its first and last
  // faces, and the path in them is that segment.
  const TriMesh mesh = testing::build(testing::planar_grid(24, 1, 0));
  MeshPoint a, b;
  const std::vector<int> strip = two_dips(mesh, a, b);
  std::vector<int> marks(mesh.triangles.size(), -1);
  Straightener s(mesh, marks);
  s.begin(a, b, strip);
  const size_t last = s.apices().size() - 1;
  ASSERT_GE(last, 4u) << "fewer than three bends";
  const int n = static_cast<int>(s.strip().size());
  Flip flip;
  ASSERT_TRUE(s.chord(0, last, ChordRoom{0, n - 1, n - 1}, flip, 8));
  EXPECT_TRUE(flip.chord);
  EXPECT_EQ(flip.first, 0);
  EXPECT_EQ(flip.last, n - 1);
  const Vec2 pa = eval_position(mesh, a).head<2>(), pb = eval_position(mesh, b).head<2>();
  std::vector<int> expected;
  for (int f : faces_crossed(mesh, pa, pb))
    if (f != strip.front() && f != strip.back()) expected.push_back(f);
  ASSERT_GT(expected.size(), 20u);
  EXPECT_EQ(flip.other, expected);
  std::vector<Apex> after;
  EXPECT_NEAR(made_length(mesh, s, flip, after), (pb - pa).norm(), 1e-12);
  EXPECT_EQ(after.size(), 2u);
  // Between neighbouring apices it is the chord of the bend between them.
  Flip one, same;
  ChordRoom room;
  ASSERT_NO_FATAL_FAILURE(semi_star_and_room(s, 2, room, one));
  same = one;
  ASSERT_TRUE(s.chord(2, room, one));
  ASSERT_TRUE(s.chord(1, 3, room, same));
  EXPECT_EQ(one.first, same.first);
  EXPECT_EQ(one.last, same.last);
  EXPECT_EQ(one.other, same.other);
}

TEST(StraightenerSpan, APassSpansTheFlatStretchesAndLeavesTheSaddlesBends) {
  // A pass on a flat grid spans the run of bends there at once: the path is the segment after one
  // pass, where flips alone take several.
  testing::Arrays grid = testing::planar_grid(24, 1, 0);
  const TriMesh flat = testing::build(grid);
  MeshPoint a, b;
  const std::vector<int> strip = two_dips(flat, a, b);
  std::vector<int> marks(flat.triangles.size(), -1);
  Straightener s(flat, marks);
  s.begin(a, b, strip);
  const size_t middle = s.apices().size() / 2;
  const int v = s.apices()[middle].vertex;
  PathStats stats;
  ASSERT_TRUE(s.pass(&stats));
  EXPECT_EQ(stats.chords_kept, 1);
  EXPECT_EQ(stats.accepted_flips, 1);
  EXPECT_NEAR(s.length(), (eval_position(flat, b) - eval_position(flat, a)).norm(), 1e-12);
  EXPECT_FALSE(s.pass(&stats));
  ShortestPathOptions off;
  off.span_min_bends = 0;
  Straightener flips(flat, marks, off);
  std::vector<int> in = strip;
  GeodesicPath path;
  PathStats passes;
  flips.straighten(a, b, in, path, &passes);
  EXPECT_GT(passes.passes, 2);
  EXPECT_NEAR(flips.length(), s.length(), 1e-12);

  // The same strip where the middle bend's vertex is a saddle (its neighbours alternately up and
  // down: angle sum above 2π): a locally shortest path may bend there, and no span crosses it (the
  // flips find whether the path stays: here it does not, by the same path with spans and without).
  std::vector<int> ring;  // (v's neighbours in turn: each fan face's corner after v's)
  for (int f : closed_fan(flat, v)) ring.push_back(flat.triangles[f][(corner_of(flat, f, v) + 1) % 3]);
  ASSERT_EQ(ring.size() % 2, 0u);
  for (size_t k = 0; k < ring.size(); ++k) grid.positions[3 * flat.file_vertex[ring[k]] + 2] = k % 2 ? 0.03 : -0.03;
  const TriMesh saddled = testing::build(grid);
  // (the same file faces and vertices: the mesh may number them otherwise)
  auto same_face = [&](int f) { return saddled.mesh_face[flat.file_face[f]]; };
  std::vector<int> saddled_strip;
  for (int f : strip) saddled_strip.push_back(same_face(f));
  const int sv = saddled.mesh_vertex[flat.file_vertex[v]];
  double theta = 0;
  for (int f : closed_fan(saddled, sv)) theta += corner_angle(saddled, f, sv);
  ASSERT_GT(theta, 2 * kPi + 1e-3);
  Straightener t(saddled, marks);
  EXPECT_FALSE(t.holds_no_bend(sv));
  EXPECT_TRUE(s.holds_no_bend(v));
  EXPECT_TRUE(t.holds_no_bend(saddled.mesh_vertex[flat.file_vertex[ring[0]]]));  // (below all its neighbours: a cone)
  EXPECT_FALSE(t.holds_no_bend(saddled.mesh_vertex[0]));                         // (a boundary)
  t.begin({same_face(a.face), a.uv}, {same_face(b.face), b.uv}, saddled_strip);
  auto bends_at = [](const Straightener& x, int w) {
    return std::any_of(x.apices().begin(), x.apices().end(), [&](const Apex& y) { return y.vertex == w; });
  };
  ASSERT_TRUE(bends_at(t, sv));
  PathStats spanned;
  ASSERT_TRUE(t.pass(&spanned));
  EXPECT_TRUE(bends_at(t, sv));
  // To the end, with spans and without: the same path.
  Straightener u(saddled, marks, off);
  std::vector<int> in_t = saddled_strip, in_u = saddled_strip;
  GeodesicPath pt, pu;
  t.straighten({same_face(a.face), a.uv}, {same_face(b.face), b.uv}, in_t, pt);
  u.straighten({same_face(a.face), a.uv}, {same_face(b.face), b.uv}, in_u, pu);
  EXPECT_NEAR(t.length(), u.length(), 1e-12);
}

// ---- Apply --------------------------------------------------------------------------------------

TEST(StraightenerApply, MakesSeveralFlipsAtOnceAsAFreshLayoutWould) {
  // The zipper's strip: the path bends at two row vertices far apart; their semi-stars are made in
  // one go, each piece of the strip between them moved rigidly.
  const TriMesh mesh = testing::build(testing::planar_grid(24, 1, 0));
  const double cell = 1.0 / 24, row = 12 * cell;
  const MeshPoint a = at_xy(mesh, 0.1, row + 0.3 * cell), b = at_xy(mesh, 0.9, row + 0.3 * cell);
  const std::vector<int> strip =
      strip_through(mesh, {a, at_xy(mesh, 0.15, row - 0.3 * cell), at_xy(mesh, 0.85, row - 0.3 * cell), b});
  std::vector<int> marks(mesh.triangles.size(), -1);
  Straightener s(mesh, marks);
  s.begin(a, b, strip);
  const std::vector<Apex>& apices = s.apices();
  ASSERT_EQ(apices.size(), 4u);
  Flip flips[2];
  for (size_t j = 1; j <= 2; ++j) {
    int first, last;
    ASSERT_TRUE(s.run_of(apices[j].vertex, apices[j].portal, first, last));
    ASSERT_TRUE(s.flip(j, turn_at(apices, j), first, last, flips[j - 1]));
  }
  ASSERT_LT(flips[0].last + 1, flips[1].first);  // they do not touch
  std::vector<int> out;
  UnfoldedStrip u;
  Splice splice;
  s.apply({&flips[0], &flips[1]}, out, u, splice);
  // The strip with both runs replaced, nothing else changed.
  std::vector<int> expected(strip.begin(), strip.begin() + flips[0].first + 1);
  expected.insert(expected.end(), flips[0].other.begin(), flips[0].other.end());
  expected.insert(expected.end(), strip.begin() + flips[0].last, strip.begin() + flips[1].first + 1);
  expected.insert(expected.end(), flips[1].other.begin(), flips[1].other.end());
  expected.insert(expected.end(), strip.begin() + flips[1].last, strip.end());
  EXPECT_EQ(out, expected);
  expect_strip(mesh, out);
  expect_fresh_layout(mesh, out, u);
  ASSERT_NE(splice.path, nullptr);
  // The funnel taking up the known path where the strips agree finds what it finds from scratch.
  std::vector<Apex> raw, spliced, fresh_raw, fresh;
  const double with = s.shorten(u, raw, spliced, &splice), without = s.shorten(u, fresh_raw, fresh, nullptr);
  EXPECT_NEAR(with, without, 1e-12);
  ASSERT_EQ(spliced.size(), fresh.size());
  for (size_t i = 0; i < fresh.size(); ++i) EXPECT_EQ(spliced[i].vertex, fresh[i].vertex);
  EXPECT_LT(with, s.length());
}

// ---- Passes -------------------------------------------------------------------------------------

TEST(StraightenerPass, OnePassStraightensAFlatVertexAndTheNextFindsNothing) {
  const TriMesh mesh = testing::build(testing::planar_grid(4, 1, 0));
  const std::vector<int> fan = closed_fan(mesh, vertex_near(mesh, {0.5, 0.5, 0}));
  ASSERT_EQ(fan.size(), 8u);
  const std::vector<int> strip(fan.begin(), fan.begin() + 6);
  const MeshPoint a = centroid(strip.front()), b = centroid(strip.back());
  std::vector<int> marks(mesh.triangles.size(), -1);
  Straightener s(mesh, marks);
  s.begin(a, b, strip);
  PathStats stats;
  EXPECT_TRUE(s.pass(&stats));
  EXPECT_EQ(stats.accepted_flips, 1);
  EXPECT_NEAR(s.length(), (eval_position(mesh, b) - eval_position(mesh, a)).norm(), 1e-12);
  EXPECT_EQ(s.strip(), (std::vector<int>{fan[0], fan[7], fan[6], fan[5]}));
  EXPECT_FALSE(s.pass(&stats));
  EXPECT_EQ(stats.accepted_flips, 1);
  EXPECT_EQ(stats.frozen_vertices, 0);
  EXPECT_TRUE(std::all_of(marks.begin(), marks.end(), [](int m) { return m == -1; }));  // lent back clean
}

TEST(StraightenerPass, MaxPassesCountsPasses) {
  // straighten with max_passes = k is begin and k passes: the same strip and length.
  const TriMesh mesh = testing::build(testing::planar_grid(24, 1, 0));
  const MeshPoint a = at_xy(mesh, 0.1, 0.8), b = at_xy(mesh, 0.9, 0.8);
  const std::vector<int> strip = strip_through(mesh, {a, at_xy(mesh, 0.51, 0.13), b});
  std::vector<int> marks(mesh.triangles.size(), -1);
  double first_length = 0;
  for (int k = 1; k <= 4; ++k) {
    ShortestPathOptions options;
    options.chords = false;  // (semi-stars and zippers: many passes to go)
    options.max_passes = k;
    Straightener whole(mesh, marks, options), steps(mesh, marks, options);
    std::vector<int> in = strip;
    GeodesicPath path;
    whole.straighten(a, b, in, path);
    EXPECT_EQ(in, path.strip);
    steps.begin(path.start, path.end, strip);
    for (int i = 0; i < k; ++i) {
      const bool more = steps.pass();
      ASSERT_TRUE(more || i >= 2) << "pass " << i;  // (the first two have work to do)
      if (!more) break;
    }
    EXPECT_EQ(path.strip, steps.strip()) << k << " passes";
    EXPECT_EQ(whole.length(), steps.length()) << k << " passes";
    if (k == 1) first_length = whole.length();
  }
  // (more passes did more: the bound was what stopped them)
  Straightener unbounded(mesh, marks);
  std::vector<int> in = strip;
  GeodesicPath path;
  unbounded.straighten(a, b, in, path);
  EXPECT_LT(unbounded.length(), first_length - 1e-6);
}

}  // namespace
}  // namespace splinekit::surface
