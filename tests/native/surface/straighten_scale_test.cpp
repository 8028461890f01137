// The straightening at scale (issue 17) on the shapes where it works hardest, a coil and a body with
// folded limbs (tests/native/surface/test_meshes.h, at the validity tests' size), whose initial strips
// from the greedy dual search zigzag (a third of their faces hold a bend of the funnel's path):
//   - after every pass, the funnel path the pass took up from the known one where the strip did not
//     change (funnel.h, Splice::between) is the one a fresh funnel finds on the whole strip;
//   - the chains' funnel (funnel.cpp) finds the same shortest path in a strip as the "simple stupid"
//     funnel that looks at every portal again after each apex (written out below as the reference);
//   - the straightened paths are locally shortest: at every bend the path turns around a vertex whose
//     angle on the far side is at least π (a saddle, or a boundary vertex), and never shorter than the
//     exact polyhedral distance (MMP, tests/native/reference);
//   - on the coil, whose inner side is a field of saddle vertices, slides (Straightener::slide) take
//     passes off the straightening and leave the paths as long as the flips one vertex at a time do;
//     each slide flips the row up to the last bend it passes and, made on its own, shortens the path;
//   - a chord (Straightener::chord) always changes the strip;
//   - windows (Straightener::windowed_pass) straighten the short stretches where a long path's last
//     bends move on their own, and leave the paths as the whole passes do, for a fraction of the
//     faces passed over;
//   - on a UV sphere, whose long thin faces make the bends slide across their rows, spans
//     (Straightener::span_pass) cross the runs of bends at once: the same paths, no bend left, in
//     under half the passes; on the knotted tube glides move the bends that lie against rows of
//     saddle vertices to where they fade at once.
#include "../reference/exact_geodesic.h"
#include "surface/geodesic.h"
#include "surface/straighten.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace splinekit::surface {
namespace {

using testing::random_point;

// The simple stupid funnel: one point per side, and back to the portal after the apex whenever one
// is made. Slower (it looks at portals again) but plainly the funnel algorithm.
void reference_funnel(const UnfoldedStrip& u, const Vec2& source, const Vec2& target, std::vector<Apex>& apices) {
  const int n = static_cast<int>(u.portals.size());
  apices.assign(1, {source, -1, -1, -1});
  Vec2 apex = source, left = apex, right = apex;
  int apex_index = -1, left_index = -1, right_index = -1, left_vertex = -1, right_vertex = -1;
  for (int i = 0; i <= n; ++i) {
    const Vec2 L = i < n ? u.left(i) : target, R = i < n ? u.right(i) : target;
    const int lv = i < n ? u.portals[i].left_vertex : -1, rv = i < n ? u.portals[i].right_vertex : -1;
    if (orient(apex, right, R) >= 0) {
      if (apex == right || apex == left || orient(apex, left, R) < 0) {
        right = R, right_index = i, right_vertex = rv;
      } else {
        apices.push_back({left, left_vertex, left_index, i});
        apex = right = left, apex_index = right_index = left_index, right_vertex = left_vertex;
        i = apex_index;
        continue;
      }
    }
    if (orient(apex, left, L) <= 0) {
      if (apex == left || apex == right || orient(apex, right, L) > 0) {
        left = L, left_index = i, left_vertex = lv;
      } else {
        apices.push_back({right, right_vertex, right_index, i});
        apex = left = right, apex_index = left_index = right_index, left_vertex = right_vertex;
        i = apex_index;
        continue;
      }
    }
  }
  if (apices.back().pos == target && apices.size() > 1) apices.pop_back();
  apices.push_back({target, -1, n, n});
}

struct Shape {
  std::string name;
  TriMesh mesh;
};

std::vector<Shape> shapes() {
  std::vector<Shape> out;
  out.push_back({"coil", testing::build(testing::coil(800, 16))});
  out.push_back({"folded body", testing::build(testing::folded_body(600, 24))});
  return out;
}

// Sum of the corner angles around v, and whether its fan is closed.
double angle_sum(const TriMesh& mesh, int v, bool& closed) {
  std::vector<int> fan;
  vertex_fan(mesh, v, fan, closed);
  double sum = 0;
  for (int f : fan) sum += corner_angle(mesh, f, v);
  return sum;
}

// Windows on the strips of these small shapes (a few hundred faces long; the defaults open them on
// strips of a thousand faces or more).
ShortestPathOptions small_windows() {
  ShortestPathOptions options;
  options.window_min_faces = 256;
  options.window_margin = 32;
  return options;
}

TEST(StraightenAtScale, SplicedFunnelsAreFreshFunnelsAfterEveryPass) {
  for (const Shape& shape : shapes()) {
    const TriMesh& mesh = shape.mesh;
    GeodesicSolver solver(mesh);
    std::vector<int> marks(mesh.triangles.size(), -1);
    Straightener s(mesh, marks, small_windows());
    std::mt19937 rng(17);
    int passes = 0, checked_bends = 0;
    for (int k = 0; k < 6; ++k) {
      const MeshPoint a = random_point(mesh, rng), b = random_point(mesh, rng);
      std::vector<int> strip;
      ASSERT_TRUE(solver.initial_strip(a, b, strip, nullptr, SearchGraph::kDual));
      MeshPoint start, end;
      ASSERT_TRUE(point_in_face(mesh, a, strip.front(), start));
      ASSERT_TRUE(point_in_face(mesh, b, strip.back(), end));
      s.begin(start, end, strip);
      for (int pass = 0; pass < 5000; ++pass) {
        const double before = s.length();
        if (!s.pass()) break;
        ++passes;
        EXPECT_LE(s.length(), before) << shape.name << " path " << k << " pass " << pass;
        std::vector<Apex> raw, fresh;
        const double length = s.shorten(s.unfolded(), raw, fresh, nullptr);
        ASSERT_NEAR(length, s.length(), 1e-9 * s.length()) << shape.name << " path " << k << " pass " << pass;
        ASSERT_EQ(fresh.size(), s.apices().size()) << shape.name << " path " << k << " pass " << pass;
        for (size_t j = 0; j < fresh.size(); ++j) {
          ASSERT_EQ(fresh[j].vertex, s.apices()[j].vertex) << shape.name << " path " << k << " pass " << pass;
          ASSERT_EQ(fresh[j].portal, s.apices()[j].portal) << shape.name << " path " << k << " pass " << pass;
        }
        checked_bends += static_cast<int>(fresh.size()) - 2;
      }
    }
    EXPECT_GT(passes, 50) << shape.name;  // (the zigzag strips take many passes)
    EXPECT_GT(checked_bends, 300) << shape.name;
  }
}

TEST(StraightenAtScale, ChainsFunnelIsTheSimpleStupidFunnel) {
  for (const Shape& shape : shapes()) {
    const TriMesh& mesh = shape.mesh;
    GeodesicSolver solver(mesh);
    std::mt19937 rng(5);
    size_t bends = 0;
    for (int k = 0; k < 20; ++k) {
      const MeshPoint a = random_point(mesh, rng), b = random_point(mesh, rng);
      std::vector<int> strip;
      ASSERT_TRUE(solver.initial_strip(a, b, strip, nullptr, SearchGraph::kDual));
      UnfoldedStrip u;
      unfold_strip(mesh, strip, u);
      MeshPoint start, end;
      ASSERT_TRUE(point_in_face(mesh, a, strip.front(), start));
      ASSERT_TRUE(point_in_face(mesh, b, strip.back(), end));
      const Vec2 source = u.map(0, start), target = u.map(static_cast<int>(strip.size()) - 1, end);
      std::vector<Apex> chains, reference;
      funnel(u, source, target, chains);
      reference_funnel(u, source, target, reference);
      EXPECT_NEAR(polyline_length(chains), polyline_length(reference), 1e-12 * polyline_length(reference))
          << shape.name << " strip " << k;
      // The same bends, once the vertices where either goes straight on are dropped.
      drop_straight(chains);
      drop_straight(reference);
      ASSERT_EQ(chains.size(), reference.size()) << shape.name << " strip " << k;
      for (size_t j = 0; j < chains.size(); ++j) {
        EXPECT_EQ(chains[j].vertex, reference[j].vertex) << shape.name << " strip " << k << " apex " << j;
        EXPECT_EQ(chains[j].portal, reference[j].portal) << shape.name << " strip " << k << " apex " << j;
      }
      bends += chains.size() - 2;
    }
    EXPECT_GT(bends, 300u) << shape.name;  // (zigzag strips: the chains are long)
  }
}

TEST(StraightenAtScale, PathsAreLocallyShortestAndNeverShorterThanExact) {
  for (const Shape& shape : shapes()) {
    const TriMesh& mesh = shape.mesh;
    GeodesicSolver solver(mesh);
    std::vector<int> marks(mesh.triangles.size(), -1);
    Straightener s(mesh, marks);
    std::mt19937 rng(29);
    int bends = 0;
    for (SearchGraph graph : {SearchGraph::kDual, SearchGraph::kRefined}) {
      for (int k = 0; k < 8; ++k) {
        const MeshPoint a = random_point(mesh, rng), b = random_point(mesh, rng);
        std::vector<int> strip;
        ASSERT_TRUE(solver.initial_strip(a, b, strip, nullptr, graph));
        GeodesicPath path;
        s.straighten(a, b, strip, path);
        const std::vector<Apex>& apices = s.apices();
        for (size_t j = 1; j + 1 < apices.size(); ++j) {
          bool closed;
          const double theta = angle_sum(mesh, apices[j].vertex, closed);
          if (!closed) continue;
          // The strip's side spans π + turn; the other side must not offer a shortcut.
          EXPECT_GE(theta - kPi - turn_at(apices, j), kPi - 1e-6) << shape.name << " path " << k << " bend " << j;
          ++bends;
        }
        EXPECT_NEAR(path_length(mesh, path), s.length(), 1e-9 * s.length()) << shape.name << " path " << k;
      }
    }
    // Between vertices, against the exact distance: a path is never shorter.
    reference::ExactGeodesic exact = testing::exact_geodesic(mesh);
    std::uniform_int_distribution<int> vertex(0, static_cast<int>(mesh.positions.size()) - 1);
    const int source = vertex(rng);
    const std::vector<double> d = exact.distances(source);
    for (int k = 0; k < 10; ++k) {
      const int target = vertex(rng);
      if (target == source) continue;
      GeodesicPath path;
      ASSERT_TRUE(solver.shortest_path(vertex_point(mesh, source), vertex_point(mesh, target), path));
      const double length = path_length(mesh, path);
      EXPECT_GE(length, d[target] * (1 - 1e-9)) << shape.name << " vertices " << source << ", " << target;
      EXPECT_LE(length, d[target] * 1.05) << shape.name << " vertices " << source << ", " << target;
    }
    EXPECT_GT(bends, 0) << shape.name;
  }
}

// The greedy search's strips between `count` pairs of random points (`seed`; strips shorter than
// `min_faces` left out) straightened twice, with the default options and with `other`: `check(k,
// ours, path, theirs)` looks at pair k's straighteners after both (`path`: the default options'
// result), and the passes' counters go to `with` and `without`. Returns the pairs compared.
template <class Check>
int straighten_both(const TriMesh& mesh, const ShortestPathOptions& other, unsigned seed, int count, size_t min_faces,
                    PathStats& with, PathStats& without, Check check) {
  GeodesicSolver solver(mesh);
  std::vector<int> marks(mesh.triangles.size(), -1);
  Straightener ours(mesh, marks), theirs(mesh, marks, other);
  std::mt19937 rng(seed);
  int compared = 0;
  for (int k = 0; k < count; ++k) {
    const MeshPoint a = random_point(mesh, rng), b = random_point(mesh, rng);
    std::vector<int> strip, same;
    EXPECT_TRUE(solver.initial_strip(a, b, strip, nullptr, SearchGraph::kDual));
    if (strip.size() < min_faces) continue;
    same = strip;
    GeodesicPath path, their_path;
    EXPECT_TRUE(ours.straighten(a, b, strip, path, &with));
    EXPECT_TRUE(theirs.straighten(a, b, same, their_path, &without));
    ++compared;
    check(k, ours, path, theirs);
  }
  return compared;
}

TEST(StraightenAtScale, SlidesTakePassesOffTheCoilAndLeaveThePathsAsLong) {
  const TriMesh mesh = testing::build(testing::coil(800, 16));
  ShortestPathOptions one_by_one;
  one_by_one.slides = false;
  PathStats with, without;
  straighten_both(mesh, one_by_one, 29, 40, 0, with, without,
                  [&](int k, const Straightener& sliding, const GeodesicPath&, const Straightener& stepping) {
                    // Both are locally shortest paths from the same strip; the slide takes the same way
                    // in fewer steps.
                    EXPECT_NEAR(sliding.length(), stepping.length(), 1e-3 * stepping.length()) << "path " << k;
                  });
  // 569 against 752 passes when written.
  EXPECT_LT(with.passes, 0.85 * without.passes);
}

// `count` pairs of random points (`seed`) on `mesh`, each one's greedy dual strip begun in a
// Straightener and straightened pass by pass: `visit(s, k)` looks at the straightener of pair k before
// each pass.
template <class Visit>
void before_each_pass(const TriMesh& mesh, unsigned seed, int count, Visit visit) {
  GeodesicSolver solver(mesh);
  std::vector<int> marks(mesh.triangles.size(), -1);
  Straightener s(mesh, marks);
  std::mt19937 rng(seed);
  for (int k = 0; k < count; ++k) {
    const MeshPoint a = random_point(mesh, rng), b = random_point(mesh, rng);
    std::vector<int> strip;
    ASSERT_TRUE(solver.initial_strip(a, b, strip, nullptr, SearchGraph::kDual));
    GeodesicPath path;
    point_in_face(mesh, a, strip.front(), path.start);
    point_in_face(mesh, b, strip.back(), path.end);
    s.begin(path.start, path.end, strip);
    for (int pass = 0; pass < 200; ++pass) {
      visit(s, k);
      if (!s.pass()) break;
    }
  }
}

// A slide flips the row of vertices a bend would slide along, from the bend back to the last bend it
// passes (apex j-back+1) and ahead to the last one there (apex j+ahead-1), not on to the bends where
// it stops: between the last bend passed and those lie side vertices the path does not touch, which
// block nothing, and flipped with the row they pushed the path round their far side (on the knotted
// tube of the benchmarks, a path 1% longer, and the same bend one vertex further on tried it again the
// next pass: 29 passes instead of 15 for a path of 900 faces). Each slide here, made on its own from
// the path as the passes leave it, shortens the path.
TEST(StraightenAtScale, ASlideFlipsTheRowUpToTheLastBendItPassesAndShortensThePath) {
  for (const Shape& shape : {Shape{"knotted tube", testing::build(testing::knot_tube(1200, 24))},
                             Shape{"coil", testing::build(testing::coil(800, 16))}}) {
    int slides = 0, shorter = 0;
    before_each_pass(shape.mesh, 43, 30, [&](Straightener& s, int k) {
      const std::vector<Apex> apices = s.apices();
      for (size_t j = 1; j + 1 < apices.size(); ++j) {
        if (apices[j].vertex < 0) continue;
        size_t ahead;
        const size_t back = s.slide(j, ahead);
        if (back == 1 && ahead == 1) continue;
        int first, last;
        Flip flip;
        if (!s.run_of(apices[j].vertex, apices[j].portal, first, last) ||
            !s.flip(j, turn_at(apices, j), first, last, flip))
          continue;
        s.zipper(j, flip, back, ahead);
        if (!flip.chain) continue;  // (the vertex's zipper failed before)
        const std::vector<int>& pivots = s.zipper_pivots();
        if (back > 1) EXPECT_EQ(pivots.front(), apices[j - back + 1].vertex) << shape.name << " path " << k;
        if (ahead > 1) EXPECT_EQ(pivots.back(), apices[j + ahead - 1].vertex) << shape.name << " path " << k;
        ++slides;
        shorter += s.lay_trial({&flip}) < s.length();
      }
    });
    // (knotted tube 109 of 109, coil 68 of 68 when written; up to the bends where the slides stop, 96
    // of 140 and 63 of 69)
    EXPECT_GT(slides, 20) << shape.name;
    EXPECT_GE(shorter, 0.95 * slides) << shape.name;
  }
}

// A chord whose walk meets the far apex's faces early and goes round it back to the strip's own
// faces changes nothing: it is no flip (it would take the faces of its neighbours' flips, pass
// after pass, and count as kept). Every chord made here replaces some face of the strip.
TEST(StraightenAtScale, AChordChangesTheStrip) {
  for (const Shape& shape : shapes()) {
    int chords = 0;
    before_each_pass(shape.mesh, 47, 30, [&](Straightener& s, int k) {
      const std::vector<Apex>& apices = s.apices();
      const int n = static_cast<int>(s.strip().size());
      for (size_t j = 1; j + 1 < apices.size(); ++j) {
        ChordRoom room{0, n - 1, n - 1};
        int unused;
        if ((apices[j - 1].vertex >= 0 &&
             !s.run_of(apices[j - 1].vertex, apices[j - 1].portal, room.p_first, unused)) ||
            (apices[j + 1].vertex >= 0 &&
             !s.run_of(apices[j + 1].vertex, apices[j + 1].portal, room.q_first, room.q_last)))
          continue;
        Flip flip;
        if (!s.chord(j, room, flip)) continue;
        ++chords;
        const std::vector<int>& faces = s.strip();
        EXPECT_FALSE(flip.other.size() + 1 == static_cast<size_t>(flip.last - flip.first) &&
                     std::equal(flip.other.begin(), flip.other.end(), faces.begin() + flip.first + 1))
            << shape.name << " path " << k << " apex " << j;
      }
    });
    EXPECT_GT(chords, 50) << shape.name;
  }
}

// The coil's long paths end by sliding a few bends along the saddle vertices of the tube's inner side,
// a vertex or two per pass, while the rest of the path stands: windows straighten those stretches on
// their own. The paths come out as long as the whole passes make them (the windows' passes flip what
// the whole passes would, in another order), locally shortest, for far fewer faces passed over. A
// longer coil than the others here (96k triangles), whose strips reach the default window_min_faces.
TEST(StraightenAtScale, WindowsStraightenTheStretchesThatMoveAndLeaveThePathsAsLong) {
  const TriMesh mesh = testing::build(testing::coil(2000, 24));
  ShortestPathOptions whole;
  whole.window_min_faces = 0;
  PathStats with, without;
  const int compared = straighten_both(
      mesh, whole, 31, 30, 256, with, without,
      [&](int k, const Straightener& windowed, const GeodesicPath& in_windows, const Straightener& passing) {
        EXPECT_NEAR(windowed.length(), passing.length(), 1e-5 * passing.length()) << "path " << k;
        EXPECT_NEAR(path_length(mesh, in_windows), windowed.length(), 1e-9 * windowed.length()) << "path " << k;
        const std::vector<Apex>& apices = windowed.apices();
        for (size_t j = 1; j + 1 < apices.size(); ++j) {
          bool closed;
          const double theta = angle_sum(mesh, apices[j].vertex, closed);
          if (closed) EXPECT_GE(theta - kPi - turn_at(apices, j), kPi - 1e-6) << "path " << k << " bend " << j;
        }
      });
  ASSERT_GT(compared, 10);
  EXPECT_GT(with.windows, 30);
  EXPECT_EQ(without.windows, 0);
  // (0.70 when written; 0.63-0.77 over other seeds)
  EXPECT_LT(with.pass_faces, 0.85 * without.pass_faces);
}

// A UV sphere's faces are long and thin (here 5:1 at the equator): across them the flips move the
// strip by a row a pass, and a long path's bends slide across the rows for a hundred passes. On a
// convex surface no locally shortest path bends at a vertex, so spans (Straightener::span_pass)
// cross each run of bends at once. The paths come out as long as the flips make them, with no bend,
// between the great circle and the sphere through the faces' nearest points, in under half the passes.
TEST(StraightenAtScale, SpansTakePassesOffAUvSphereAndLeaveThePathsAsLong) {
  const TriMesh mesh = testing::build(testing::uv_sphere(800, 50));
  ShortestPathOptions flips_only;
  flips_only.span_min_bends = 0;
  PathStats with, without;
  straighten_both(mesh, flips_only, 37, 30, 0, with, without,
                  [&](int k, const Straightener& spanning, const GeodesicPath& spanned, const Straightener& flipping) {
                    EXPECT_NEAR(spanning.length(), flipping.length(), 1e-7 * flipping.length()) << "path " << k;
                    EXPECT_NEAR(path_length(mesh, spanned), spanning.length(), 1e-9 * spanning.length())
                        << "path " << k;
                    EXPECT_EQ(spanning.apices().size(), 2u) << "path " << k;
                    // The mesh lies inside the unit sphere, its vertices on it: a path on it is at most the great
                    // circle arc between its ends' directions long (the shorter one, unless the ends are nearly
                    // opposite: none here) and at least that arc on the sphere through the faces' nearest points.
                    const Vec3 pa = eval_position(mesh, spanned.start), pb = eval_position(mesh, spanned.end);
                    const double arc = std::acos(std::clamp(pa.normalized().dot(pb.normalized()), -1.0, 1.0));
                    EXPECT_LE(spanning.length(), arc * (1 + 1e-9)) << "path " << k;
                    EXPECT_GE(spanning.length(), std::cos(kPi / 50) * arc) << "path " << k;
                  });
  EXPECT_GT(with.chords_kept, 0);
  // (0.40x the passes when written)
  EXPECT_LT(with.passes, 0.5 * without.passes);
}

// On the knotted tube (faces six times longer round the tube than along it) a long path's last bends
// lie against rows of saddle vertices along the tube's inner side that the path does not touch, and
// each flip moves such a bend to the next vertex of the row, by that vertex's excess smaller: a
// bend of 0.1 rad against vertices of excess 0.0018 took 35 passes to fade. Glides
// (Straightener::glide) flip the row's vertices up to where the bend fades at once. The same
// locally shortest paths, in fewer passes.
TEST(StraightenAtScale, GlidesTakePassesOffTheKnottedTubeAndLeaveThePathsAsLong) {
  const TriMesh mesh = testing::build(testing::knot_tube(1200, 24));
  ShortestPathOptions vertex_by_vertex;
  vertex_by_vertex.glides = false;
  PathStats with, without;
  straighten_both(mesh, vertex_by_vertex, 41, 30, 0, with, without,
                  [&](int k, const Straightener& gliding, const GeodesicPath&, const Straightener& stepping) {
                    EXPECT_NEAR(gliding.length(), stepping.length(), 1e-6 * stepping.length()) << "path " << k;
                  });
  EXPECT_LT(with.passes, 0.9 * without.passes);  // (0.76x when written)
}

TEST(StraightenAtScale, VertexSetIsASet) {
  VertexSet set;
  std::set<int> reference;
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> v(0, 5000);
  for (int round = 0; round < 3; ++round) {
    for (int i = 0; i < 700 * (round + 1); ++i) {
      const int x = v(rng);
      set.insert(x, -1.0);
      set.insert(x, 0.5 * x + round);  // (a second insert gives it its value)
      reference.insert(x);
    }
    EXPECT_EQ(set.size(), reference.size());
    for (int x = 0; x <= 5000; ++x) {
      ASSERT_EQ(set.contains(x), reference.count(x) > 0) << x;
      if (set.contains(x)) ASSERT_EQ(*set.find(x), 0.5 * x + round) << x;
    }
    set.clear();
    reference.clear();
    for (int x = 0; x <= 5000; ++x) ASSERT_FALSE(set.contains(x)) << x;
  }
}

}  // namespace
}  // namespace splinekit::surface
