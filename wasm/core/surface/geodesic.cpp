#include "surface/geodesic.h"

#include <algorithm>
#include <limits>
#include <tuple>

namespace splinekit::surface {

GeodesicSolver::GeodesicSolver(const TriMesh& mesh, const ShortestPathOptions& options)
    : mesh_(mesh), search_(mesh, options), straightener_(mesh, search_.face_marks(), options) {}

GeodesicSolver::~GeodesicSolver() = default;

MeshStatus GeodesicSolver::set_coarse_guide(const int* triangles, int count, std::string& error) {
  std::unique_ptr<CoarseGuide> guide;
  if (CoarseGuide::build(mesh_, triangles, count, straightener_.options, guide, error) != MeshStatus::kOk)
    return MeshStatus::kInvalidInput;
  guide_ = std::move(guide);
  return MeshStatus::kOk;
}

bool GeodesicSolver::shortest_path(const MeshPoint& a, const MeshPoint& b, GeodesicPath& path, PathStats* stats,
                                   SearchGraph graph) {
  // From the end that comes first (by face, then barycentrics), reversed if need be: where locally
  // shortest paths lie close together, the search and the straightening from either end may settle
  // on different ones, and the path between two points should not depend on their order.
  const auto before = [](const MeshPoint& x, const MeshPoint& y) {
    return std::tie(x.face, x.uv.x(), x.uv.y()) < std::tie(y.face, y.uv.x(), y.uv.y());
  };
  if (before(b, a)) {
    const bool reached = shortest_path(b, a, path, stats, graph);
    path = reversed(mesh_, path);
    return reached;
  }
  if (graph == SearchGraph::kDual && guided_strip(a, b, stats)) {
    straightener_.straighten(a, b, strip_, path, stats);
    return true;
  }
  // A long refined search keeps to the corridor of the guide's near-shortest ways.
  const double slack = straightener_.options.guide_corridor_slack;
  bool searched = false;
  if (graph == SearchGraph::kRefined && slack > 0 && far_apart(a, b) &&
      guide_->corridor(a, b, slack, straightener_.options.guide_corridor_edges, search_.face_marks(), corridor_)) {
    searched = search_.initial_strip(a, b, strip_, stats, graph, &corridor_);
    search_length_ = search_.last_length();
    if (stats) ++stats->guided;
  }
  if (!searched && !initial_strip(a, b, strip_, stats, graph)) {
    path = GeodesicPath{a, b, {}, {}, {}};
    return false;
  }
  const ShortestPathOptions& options = straightener_.options;
  const int reverse_faces = options.dual_reverse_search_faces;
  if (graph == SearchGraph::kDual && reverse_faces > 0 && strip_.size() >= static_cast<size_t>(reverse_faces)) {
    // A long greedy strip: the other candidates, the one whose funnel path is shortest straightened.
    // The search from b is left out when the landmark descent's strip beat the forward one (on the coil
    // mostly: 0.90x its curves' instructions, the same curves; elsewhere within 1%, curves up to 0.14%
    // longer; BENCHMARKS.md, "Surface at scale", Landmark descent).
    double shortest = funnel_length(a, b, strip_);
    bool descended = false;
    if (options.landmark_descent && descent_strip(a, b, shortest, back_, stats)) {
      const double length = funnel_length(a, b, back_);
      descended = length < shortest;
      if (descended) strip_.swap(back_), search_length_ = std::numeric_limits<double>::quiet_NaN(), shortest = length;
    }
    if (!descended && search_.initial_strip(b, a, back_, stats, graph)) {
      std::reverse(back_.begin(), back_.end());
      const double length = funnel_length(a, b, back_);
      if (length < shortest) strip_.swap(back_), search_length_ = search_.last_length(), shortest = length;
    }
  }
  straightener_.straighten(a, b, strip_, path, stats);
  return true;
}

bool GeodesicSolver::far_apart(const MeshPoint& a, const MeshPoint& b) const {
  const int faces = straightener_.options.coarse_guide_faces;
  if (!guide_ || faces <= 0) return false;
  // Ends whose distance is bounded below by fewer guide edges than that: a short path, which the
  // greedy search finds at once (the guide's would cost its search and the walks to kept vertices).
  const double apart = std::max((eval_position(mesh_, a) - eval_position(mesh_, b)).norm(),
                                search_.landmarks().bound_between(a.face, b.face));
  return apart >= faces * guide_->mean_edge();
}

bool GeodesicSolver::guided_strip(const MeshPoint& a, const MeshPoint& b, PathStats* stats) {
  const int faces = straightener_.options.coarse_guide_faces;
  if (!far_apart(a, b) || !guide_->strip(a, b, faces, search_, strip_, stats)) return false;
  search_length_ = std::numeric_limits<double>::quiet_NaN();
  if (stats) ++stats->guided;
  return true;
}

bool GeodesicSolver::descent_strip(const MeshPoint& a, const MeshPoint& b, double shortest, std::vector<int>& strip,
                                   PathStats* stats) {
  const Landmarks& marks = search_.landmarks();
  const int l = marks.best_between(a.face, b.face);
  if (l < 0) return false;
  // Down from the end farther from the landmark (the other lies on the way to it, as far as the
  // bound tells), to the other end's level; the greedy search from there to that end. `shortest`:
  // the funnel length of the best strip so far.
  const bool from_a = marks.value(a.face, l) > marks.value(b.face, l);
  const MeshPoint& to = from_a ? b : a;
  marks.descend(mesh_, search_.centroids(), l, (from_a ? a : b).face, marks.value(to.face, l), strip);
  const MeshPoint level{strip.back(), Vec2(1.0 / 3, 1.0 / 3)};
  // Level with `to` but far from it: the landmark's way passes elsewhere (a fold, a limb), and the
  // search on would be long for a candidate that seldom wins.
  if ((eval_position(mesh_, level) - eval_position(mesh_, to)).norm() >
      straightener_.options.landmark_descent_gap * shortest)
    return false;
  if (!search_.initial_strip(level, to, tail_, stats, SearchGraph::kDual)) return false;
  strip.insert(strip.end(), tail_.begin() + 1, tail_.end());
  remove_loops(strip, search_.face_marks());
  if (!from_a) std::reverse(strip.begin(), strip.end());
  return true;
}

double GeodesicSolver::funnel_length(const MeshPoint& a, const MeshPoint& b, const std::vector<int>& strip) {
  MeshPoint start, end;
  point_in_face(mesh_, a, strip.front(), start);
  point_in_face(mesh_, b, strip.back(), end);
  straightener_.begin(start, end, strip);
  return straightener_.length();
}

namespace {

// Appends to `strip` (ending at a face that holds p) the faces from there to `face`, which also holds
// p: nothing when it is the same face, `face` when adjacent, else the way around p's vertex that
// spans the smaller angle (the other way the path would wrap around the vertex's far side, which on
// a cone such as a cube's corner straightens into a different, longer geodesic). fan: scratch.
bool walk_to(const TriMesh& mesh, const MeshPoint& p, int face, std::vector<int>& strip, std::vector<int>& fan) {
  const int from = strip.back();
  if (from == face) return true;
  if (edge_to(mesh, from, face) >= 0) {
    strip.push_back(face);
    return true;
  }
  MeshPoint on_from;
  if (!point_in_face(mesh, p, from, on_from)) return false;
  const PointLocation where = locate(mesh, on_from);
  if (where.kind != PointLocation::Kind::kVertex) return false;
  bool closed;
  vertex_fan(mesh, where.index, fan, closed);
  const int n = static_cast<int>(fan.size());
  const int i = static_cast<int>(std::find(fan.begin(), fan.end(), from) - fan.begin());
  const int j = static_cast<int>(std::find(fan.begin(), fan.end(), face) - fan.begin());
  if (i == n || j == n) return false;
  // Forward (i -> j in fan order) or backward; an open fan cannot wrap around.
  const int forward = (j - i + n) % n, backward = (i - j + n) % n;
  auto angle = [&](int step, int count) {  // corner angles at the vertex of the faces strictly between
    double sum = 0;
    for (int s = 1; s < count; ++s) sum += corner_angle(mesh, fan[((i + step * s) % n + n) % n], where.index);
    return sum;
  };
  const bool go_forward = closed ? angle(1, forward) <= angle(-1, backward) : j > i;
  const int steps = go_forward ? forward : backward;
  for (int s = 1; s <= steps; ++s) strip.push_back(fan[((go_forward ? i + s : i - s) % n + n) % n]);
  return true;
}

}  // namespace

bool GeodesicSolver::straighten_through(const std::vector<GeodesicPath>& pieces, GeodesicPath& path, PathStats* stats,
                                        int max_passes) {
  std::vector<int>& strip = strip_;
  strip.clear();
  for (const GeodesicPath& piece : pieces) {
    if (piece.strip.empty()) return false;
    if (strip.empty()) {
      strip.push_back(piece.strip.front());
    } else if (!walk_to(mesh_, piece.start, piece.strip.front(), strip, fan_)) {
      return false;
    }
    strip.insert(strip.end(), piece.strip.begin() + 1, piece.strip.end());
  }
  remove_loops(strip, search_.face_marks());
  return straightener_.straighten(pieces.front().start, pieces.back().end, strip, path, stats, max_passes);
}

}  // namespace splinekit::surface
