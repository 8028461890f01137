#include "surface/dual_search.h"

#include "surface/path.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <utility>

namespace splinekit::surface {

namespace {

// Faces that contain a point: its face, the neighbour across the edge it lies on, or its vertex's fan.
void faces_of_point(const TriMesh& mesh, const MeshPoint& p, std::vector<int>& faces) {
  faces.clear();
  const PointLocation where = locate(mesh, p);
  if (where.kind == PointLocation::Kind::kVertex) {
    bool closed;
    vertex_fan(mesh, where.index, faces, closed);
    if (std::find(faces.begin(), faces.end(), p.face) == faces.end()) faces.push_back(p.face);
    return;
  }
  faces.push_back(p.face);
  if (where.kind == PointLocation::Kind::kEdge && mesh.adjacency[p.face][where.index] >= 0)
    faces.push_back(mesh.adjacency[p.face][where.index]);
}

}  // namespace

DualSearch::DualSearch(const TriMesh& mesh, const ShortestPathOptions& options)
    : mesh_(mesh),
      dual_weight_(options.dual_heuristic_weight),
      landmark_weight_(options.landmark_weight),
      refined_landmark_scale_(options.refined_landmark_scale) {
  const int nf = static_cast<int>(mesh.triangles.size());
  graph_.faces = nf;
  graph_.steiner = std::max(1, options.steiner);
  graph_.long_edge = options.long_edge_fraction * mesh.scale;
  graph_.halfedge_edge.assign(3 * static_cast<size_t>(nf), -1);
  for (int f = 0; f < nf; ++f) {
    const auto& t = mesh.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const int g = mesh.adjacency[f][k];
      if (g >= 0 && g < f) {  // numbered from the other side already
        graph_.halfedge_edge[3 * f + k] = graph_.halfedge_edge[3 * g + edge_to(mesh, g, f)];
        continue;
      }
      graph_.halfedge_edge[3 * f + k] = static_cast<int>(graph_.edge_halfedge.size());
      graph_.edge_halfedge.push_back(3 * f + k);
      const double len = (mesh.positions[t[(k + 1) % 3]] - mesh.positions[t[k]]).norm();
      const int count = len > graph_.long_edge ? static_cast<int>(std::ceil(len / graph_.long_edge)) - 1 : 0;
      if (count > graph_.steiner) {
        if (graph_.long_first.empty()) graph_.long_first.push_back(0);
        graph_.long_edges.push_back(static_cast<int>(graph_.edge_halfedge.size()) - 1);
        graph_.long_first.push_back(graph_.long_first.back() + count);
      }
    }
  }
  graph_.edges = static_cast<int>(graph_.edge_halfedge.size());
  graph_.long_edges.shrink_to_fit();
  graph_.long_first.shrink_to_fit();
  if (!graph_.long_edges.empty()) {
    graph_.long_bits.assign(graph_.edges / 64 + 1, 0);
    for (int e : graph_.long_edges) graph_.long_bits[e >> 6] |= uint64_t{1} << (e & 63);
  }
  face_slot_.assign(nf, -1);
  edge_slot_.assign(graph_.edges, -1);
  origin_ = mesh.centre;
  centroids_.resize(nf);
  for (int f = 0; f < nf; ++f) {
    const auto& t = mesh.triangles[f];
    centroids_[f] = local((mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]) / 3);
  }
  landmarks_ = Landmarks(mesh, centroids_, options.landmarks, options.landmark_min_faces);
  // (not measured where it would not be used: the coarse guide's exact search)
  const bool refined_share = refined_landmark_scale_ <= 0 && options.refined_landmark_share > 0 && !landmarks_.empty();
  if (options.dual_stretch_weight > 0 || refined_share) dual_stretch_ = measure_stretch();
  if (options.dual_stretch_weight > 0)
    dual_weight_ = std::max(dual_weight_, options.dual_stretch_weight * dual_stretch_);
  if (refined_share) refined_landmark_scale_ = options.refined_landmark_share / dual_stretch_;
}

double DualSearch::measure_stretch() {
  constexpr int kSamples = 32;
  constexpr float kReach = 20;
  constexpr int kMaxFaces = 8192;  // per sample (a large face among small ones would reach too many)
  const int nf = graph_.faces;
  std::vector<float> ratios, dist;
  std::vector<int> touched;
  using Entry = std::pair<float, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for (int i = 0; i < kSamples && nf > 0; ++i) {
    const int s = static_cast<int>((int64_t{2} * i + 1) * nf / (2 * kSamples));
    const auto& t = mesh_.triangles[s];
    const float size = static_cast<float>(std::sqrt(
        0.5 *
        (mesh_.positions[t[1]] - mesh_.positions[t[0]]).cross(mesh_.positions[t[2]] - mesh_.positions[t[0]]).norm()));
    if (!(size > 0)) continue;
    const float reach = kReach * size;
    // (face_slot_ numbers the faces touched, into dist; -1 again afterwards)
    touched.assign(1, s), dist.assign(1, 0.f), face_slot_[s] = 0;
    queue.push({0.f, s});
    for (int expanded = 0; !queue.empty() && expanded < kMaxFaces; ++expanded) {
      const auto [d, f] = queue.top();
      queue.pop();
      if (d > dist[face_slot_[f]]) continue;
      const float straight = (centroids_[f] - centroids_[s]).norm();
      if (straight > reach) continue;
      if (straight > reach / 2) ratios.push_back(d / straight);
      for (int g : mesh_.adjacency[f]) {
        if (g < 0) continue;
        int& slot = face_slot_[g];
        if (slot < 0) {
          slot = static_cast<int>(dist.size());
          dist.push_back(std::numeric_limits<float>::infinity());
          touched.push_back(g);
        }
        const float dg = d + (centroids_[g] - centroids_[f]).norm();
        if (dg < dist[slot]) dist[slot] = dg, queue.push({dg, g});
      }
    }
    for (int f : touched) face_slot_[f] = -1;
    queue = {};
  }
  if (ratios.empty()) return 1;
  const auto p90 = ratios.begin() + static_cast<std::ptrdiff_t>(0.9 * static_cast<double>(ratios.size() - 1));
  std::nth_element(ratios.begin(), p90, ratios.end());
  return *p90;
}

size_t DualSearch::bytes() const {
  return (graph_.halfedge_edge.capacity() + graph_.edge_halfedge.capacity() + graph_.long_edges.capacity() +
          graph_.long_first.capacity()) *
             sizeof(int) +
         graph_.long_bits.capacity() * sizeof(uint64_t) +
         (face_slot_.capacity() + edge_slot_.capacity()) * sizeof(int) + visits_.capacity() * sizeof(Visit) +
         centroids_.capacity() * sizeof(centroids_[0]) + corridor_bits_.capacity() * sizeof(uint64_t) +
         landmarks_.bytes();
}

// Position of graph node `node` (on edge e, -1 for a face node), relative to origin_: a face centroid,
// or a point along an edge.
Vec3 DualSearch::node_position(int node, int e) const {
  if (node < graph_.faces) return centroids_[node].cast<double>();
  const auto [first, end] = graph_.node_range(e);
  const int count = end - first;
  const int h = graph_.edge_halfedge[e];
  const auto& t = mesh_.triangles[h / 3];
  const double s = double(node - first + 1) / (count + 1);
  return (1 - s) * (mesh_.positions[t[h % 3]] - origin_) + s * (mesh_.positions[t[(h % 3 + 1) % 3]] - origin_);
}

float DualSearch::edge_length(int e) const {
  const int h = graph_.edge_halfedge[e];
  const auto& t = mesh_.triangles[h / 3];
  return static_cast<float>((mesh_.positions[t[(h % 3 + 1) % 3]] - mesh_.positions[t[h % 3]]).norm());
}

// The faces of a node: itself, or the one or two faces of its edge.
static void node_faces(const TriMesh& mesh, const DualGraph& graph, int node, int faces[2]) {
  if (node < graph.faces) {
    faces[0] = node, faces[1] = -1;
    return;
  }
  const int h = graph.edge_halfedge[graph.edge_of_node(node)];
  faces[0] = h / 3;
  faces[1] = mesh.adjacency[h / 3][h % 3];
}

int DualSearch::link_face(int a, int b) const {
  int fa[2], fb[2];
  node_faces(mesh_, graph_, a, fa);
  node_faces(mesh_, graph_, b, fb);
  for (int x : fa)
    for (int y : fb)
      if (x >= 0 && x == y) return x;
  return -1;
}

namespace {

// Straight runs through the refined graph (the refined search's windows). A node reached across a
// chain of faces keeps a pseudo-source σ (the source point, or a node where the path bent), laid
// flat with those faces, its distance d(σ), and the stretch [lo, hi] of the node's own edge through
// which σ sees straight along the whole chain: every point of that stretch is at distance
// d(σ) + |σ - x| by a straight segment on the unfolded faces. Going on into the next face f, a node
// p of f that σ sees through the stretch gets d(σ) + |σ - p| (a real path on the surface, no longer
// than the graph's hops through the node), and its own stretch is where the cone from σ through
// [lo, hi] meets p's edge; a node that σ does not see gets the shorter of the way round an end of
// the node's edge that the stretch reaches (with that vertex as its pseudo-source) and the hop
// from the node (with the node as its pseudo-source). The window of Mitchell, Mount &
// Papadimitriou ("The discrete geodesic problem", SIAM J. Comput. 16(4), 1987), one per node:
// distances follow the surface's straight lines rather than the graph's zigzag between the nodes
// on the edges, which on thin tubes and long faces (a limb, a coil) is what made the search pick a
// path a few percent longer than a neighbouring one.
//
// In f's plane, with the edge e from A to B along unit x and unit y across it into f, σ lies at
// (xs, ys) with ys <= 0 (behind e, or on it).
struct Window {
  Eigen::Vector3f a, x, y;
  float xs = 0, ys = 0, dist = 0, lo = 0, hi = 0, length = 0;
  // Distances to e's ends A and B, by straight runs from σ when its window reaches them (infinity
  // otherwise): a path that σ does not see straight may bend round them.
  float to_a = std::numeric_limits<float>::infinity(), to_b = std::numeric_limits<float>::infinity();
  bool valid = false;
  // The window of node record `v` on the edge of half-edge h (3g + k), going on into face f; none
  // (distance() infinite) when `use` is false.
  // (Positions relative to `origin`, as the search's.)
  Window(const TriMesh& mesh, const Vec3& origin, int h, int f, const DualSearch::Visit& v, bool use) {
    if (!use) return;
    const auto& t = mesh.triangles[h / 3];
    const Vec3& pa = mesh.positions[t[h % 3]];
    a = (pa - origin).cast<float>();
    x = (mesh.positions[t[(h % 3 + 1) % 3]] - pa).cast<float>();
    length = x.norm();
    const auto& tf = mesh.triangles[f];
    int c = 0;
    while (c < 2 && (tf[c] == t[h % 3] || tf[c] == t[(h % 3 + 1) % 3])) ++c;
    const Eigen::Vector3f ac = (mesh.positions[tf[c]] - pa).cast<float>();
    if (!(length > 0)) return;
    x /= length;
    y = ac - ac.dot(x) * x;
    const float height = y.norm();
    if (!(height > 0)) return;
    y /= height;
    const Eigen::Vector3f as = v.source - a;
    xs = as.dot(x);
    ys = -(as - xs * x).norm();
    dist = v.source_dist, lo = v.lo, hi = v.hi;
    valid = true;
    const float slack = 1e-5f * length;
    if (lo <= slack) to_a = dist + std::sqrt(xs * xs + ys * ys);
    if (hi >= length - slack) to_b = dist + std::sqrt((length - xs) * (length - xs) + ys * ys);
  }
  // Around e's ends: the shorter way to p of f by A or B (a vertex of f, which sees all of f), and
  // which (0: A, 1: B); infinity when the window reaches neither.
  float around(const Eigen::Vector3f& p, int& end) const {
    end = 0;
    if (to_a == std::numeric_limits<float>::infinity() && to_b == to_a) return to_a;  // (no need to measure)
    const float via_a = to_a + (p - a).norm(), via_b = to_b + (p - (a + length * x)).norm();
    end = via_b < via_a ? 1 : 0;
    return std::min(via_a, via_b);
  }
  // Where the segment from σ to the point (px, py) of f crosses e's line (x along e).
  float crossing(float px, float py) const { return ys < 0 ? xs + (px - xs) * (-ys / (py - ys)) : xs; }
  // d(σ) + |σ - p| for p on f when σ sees p through [lo, hi], else infinity.
  float distance(const Eigen::Vector3f& p) const {
    if (!valid) return std::numeric_limits<float>::infinity();
    const Eigen::Vector3f ap = p - a;
    const float px = ap.dot(x), py = std::max(0.f, ap.dot(y));
    const float c = crossing(px, py), slack = 1e-5f * (hi - lo + 1e-6f);
    if (!(c >= lo - slack && c <= hi + slack)) return std::numeric_limits<float>::infinity();
    return dist + std::sqrt((px - xs) * (px - xs) + (py - ys) * (py - ys));
  }
  // Node record v, on the edge of half-edge h of f, just reached through this window: its
  // pseudo-source (σ laid in f's plane), distance and stretch (the cone's trace on its edge).
  void pass_on(const TriMesh& mesh, const Vec3& origin, int h, DualSearch::Visit& v) const {
    v.source = a + xs * x + ys * y;
    v.source_dist = dist;
    const auto& t = mesh.triangles[h / 3];
    const Eigen::Vector3f q0 = (mesh.positions[t[h % 3]] - origin).cast<float>() - a,
                          q1 = (mesh.positions[t[(h % 3 + 1) % 3]] - origin).cast<float>() - a;
    const float x0 = q0.dot(x), y0 = std::max(0.f, q0.dot(y)), x1 = q1.dot(x), y1 = std::max(0.f, q1.dot(y));
    const float length = (q1 - q0).norm();
    if (!(ys < 0)) {  // σ on e: it sees all of f
      v.lo = 0, v.hi = length;
      return;
    }
    // Along the edge, s in [0, length], the segment from σ to the edge's point crosses e's line at
    // crossing(s), which runs monotonically from c0 (s = 0) to c1 (s = length): the stretch is
    // where it lies in [lo, hi]. Where lo or hi lies strictly between c0 and c1, solve
    // crossing(s) = c: (x(s) - xs)(-ys) = (c - xs)(y(s) - ys), linear in s. (The line's solution
    // outside the edge can lie behind σ, where crossing() is not that of a segment from σ: only the
    // edge's own stretch is solved for.)
    const float c0 = crossing(x0, y0), c1 = crossing(x1, y1);
    auto at = [&](float c) {
      const float dx = x1 - x0, dy = y1 - y0;
      const float num = (c - xs) * (y0 - ys) + (x0 - xs) * ys, den = -ys * dx - (c - xs) * dy;
      const float s = den != 0 ? length * (num / den) : length * (c - c0) / (c1 - c0);
      return std::clamp(s, 0.f, length);
    };
    float from, to;
    if (c0 <= c1) {
      from = c0 >= lo ? 0 : lo <= c1 ? at(lo) : length;
      to = c1 <= hi ? length : hi >= c0 ? at(hi) : 0;
    } else {
      from = c0 <= hi ? 0 : hi >= c1 ? at(hi) : length;
      to = c1 >= lo ? length : lo <= c0 ? at(lo) : 0;
    }
    // (A node seen within the visibility test's slack, where the stretch is empty: a point.)
    if (from > to) from = to = (from + to) / 2;
    v.lo = from, v.hi = to;
  }
};

}  // namespace

bool DualSearch::initial_strip(const MeshPoint& a, const MeshPoint& b, std::vector<int>& strip, PathStats* stats,
                               SearchGraph graph, const std::vector<int>* corridor) {
  const bool dual = graph == SearchGraph::kDual;
  strip.clear();
  last_length_ = std::numeric_limits<double>::infinity();
  const int nf = graph_.faces;
  std::vector<int>& sources = sources_;
  std::vector<int>& targets = targets_;
  faces_of_point(mesh_, a, sources);
  faces_of_point(mesh_, b, targets);
  for (int s : sources) {
    if (std::find(targets.begin(), targets.end(), s) != targets.end()) {
      strip.push_back(s);
      last_length_ = 0;
      return true;
    }
  }
  // The faces the search may enter: the corridor's and the ends', or all.
  if (corridor) {
    if (corridor_bits_.empty()) corridor_bits_.assign((static_cast<size_t>(nf) + 63) / 64, 0);
    auto mark = [&](int f) { corridor_bits_[f >> 6] |= uint64_t{1} << (f & 63); };
    for (int f : *corridor) mark(f);
    for (int f : sources) mark(f);
    for (int f : targets) mark(f);
  }
  auto allowed = [&](int f) { return !corridor || (corridor_bits_[f >> 6] >> (f & 63) & 1); };
  // (Relative to origin_, as the nodes' positions.)
  const Vec3 pa = eval_position(mesh_, a) - origin_;
  const Vec3 pb = eval_position(mesh_, b) - origin_;
  const Eigen::Vector3f pbf = pb.cast<float>();
  const double weight = dual ? dual_weight_ : 1.0;
  // The landmark term (landmarks.h): admissible on the dual graph; scaled down on the refined one
  // (ShortestPathOptions::refined_landmark_share), and there used only where it bounds the way from
  // a's face farther than space does (a term of weight 0 is not computed at all).
  const double landmark_weight = dual ? landmark_weight_ : refined_landmark_scale_;
  bool use_landmarks = !landmarks_.empty() && landmark_weight > 0;
  if (use_landmarks) {
    landmarks_.set_target(targets.data(), static_cast<int>(targets.size()));
    if (!dual) use_landmarks = landmark_weight * landmarks_.bound(sources.front()) > (pa - pb).norm();
  }
  // The A* term of a node at p on face f (its own face, or one of its edge's): the larger of the
  // Euclidean and the landmark bounds, the latter moved from f's centroid to p.
  auto heuristic = [&](const Vec3& p, int f) {
    double h = weight * (p - pb).norm();
    if (use_landmarks) {
      const double bound = landmarks_.bound(f);
      if (bound > 0) h = std::max(h, landmark_weight * (bound - (p - centroids_[f].cast<double>()).norm()));
    }
    return static_cast<float>(h);
  };
  RadixQueue& queue = queue_;
  queue.clear();
  visits_.clear();
  // The record of a node on edge e (-1: a face node), made on first touch (its position is looked at
  // many times); the nodes of an edge get theirs together.
  auto visit = [&](int node, int e) -> int {
    if (e < 0) {
      int& slot = face_slot_[node];
      if (slot < 0) {
        const Vec3 p = node_position(node, -1);
        slot = static_cast<int>(visits_.size());
        visits_.push_back({std::numeric_limits<float>::infinity(), heuristic(p, node), node, -1, p.cast<float>(), false,
                           -1, Eigen::Vector3f::Zero(), 0.f, 0.f, 0.f});
      }
      return slot;
    }
    const auto [first, end] = graph_.node_range(e);
    int& slot = edge_slot_[e];
    if (slot < 0) {
      slot = static_cast<int>(visits_.size());
      const int f = graph_.edge_halfedge[e] / 3;
      for (int n = first; n < end; ++n) {
        const Vec3 p = node_position(n, e);
        visits_.push_back({std::numeric_limits<float>::infinity(), heuristic(p, f), n, -1, p.cast<float>(), false, -1,
                           Eigen::Vector3f::Zero(), 0.f, 0.f, 0.f});
      }
    }
    return slot + node - first;
  };
  auto key = [&](const Visit& v) { return v.dist + v.heuristic; };
  // Relaxes record r (a node) from node `from` at `at`, `d_from` from the source.
  auto relax_record = [&](int r, int from, const Eigen::Vector3f& at, float d_from) {
    Visit& v = visits_[r];
    if (v.closed) return;
    const float d = d_from + (v.position - at).norm();
    if (d >= v.dist) return;
    v.dist = d;
    v.parent = from;
    queue.push(key(v), r);
  };
  // Relaxes `node` (on edge e) from `from` at `at`, `d_from` from the source.
  auto relax = [&](int node, int e, int from, const Eigen::Vector3f& at, float d_from) {
    relax_record(visit(node, e), from, at, d_from);
  };

  // The nodes of face f a path goes on to: in the dual graph its centroid (each(f, -1)); in the
  // refined graph the nodes on its edges but those on `skip_edge` (each(node, edge)). The refined
  // search leaves the centroids out: a centroid lies on one face only, so a path through it joins
  // two nodes of that face, which are linked directly by a segment no longer than the two (the
  // distances are the same without them, and ~1/7 of the nodes and 2 of an edge node's 18 links
  // are not looked at).
  auto for_face_nodes = [&](int f, int skip_edge, auto&& each) {
    if (dual) {
      each(f, -1);
      return;
    }
    for (int k = 0; k < 3; ++k) {
      const int e = graph_.halfedge_edge[3 * f + k];
      if (e == skip_edge) continue;
      for (auto [n, end] = graph_.node_range(e); n < end; ++n) each(n, e);
    }
  };
  auto is_target = [&](int f) { return std::find(targets.begin(), targets.end(), f) != targets.end(); };
  // Best arrival into a target face so far: from node, into face, total length.
  int best_node = -1, best_face = -1;
  float best = std::numeric_limits<float>::infinity();

  const Eigen::Vector3f paf = pa.cast<float>();
  for (int s : sources)
    for_face_nodes(s, -1, [&](int node, int e) {
      const int r = visit(node, e);
      relax_record(r, -1, paf, 0.f);
      // An edge node's window from the source point, which sees all of the node's edge (the first
      // source face to reach the node gives it).
      Visit& v = visits_[r];
      if (e >= 0 && v.via < 0) v.via = s, v.source = paf, v.source_dist = 0, v.lo = 0, v.hi = edge_length(e);
    });

  int visited = 0;
  while (!queue.empty()) {
    const auto [top_key, r] = queue.pop();
    if (top_key != key(visits_[r])) continue;  // stale: the node was reached shorter since
    // A* bound: the smallest key reaches the best arrival, which nothing left can improve.
    if (top_key >= best) break;
    visits_[r].closed = true;
    ++visited;
    // (copies: visit() may grow visits_)
    const int u = visits_[r].node;
    const float du = visits_[r].dist;
    const Eigen::Vector3f pu = visits_[r].position;
    // Arrival: the straight segment from u to b inside target face f (weighted as the A* term was).
    auto arrive = [&](int f) {
      if (!is_target(f)) return;
      const float total = du + static_cast<float>(weight) * (pu - pbf).norm();
      if (total < best) best = total, best_node = u, best_face = f;
    };
    if (dual) {
      arrive(u);
      for (int g : mesh_.adjacency[u])
        if (g >= 0 && allowed(g)) relax(g, -1, u, pu, du);
    } else {  // (an edge node: the refined search has no centroid nodes)
      int faces[2];
      node_faces(mesh_, graph_, u, faces);
      const int e = graph_.edge_of_node(u);
      for (int f : faces) {
        if (f < 0 || !allowed(f)) continue;
        // On into f: straight from u's pseudo-source where it sees through u's window, else from u.
        const Visit& vu = visits_[r];
        const Window window(mesh_, origin_, graph_.edge_halfedge[e], f, vu, f != vu.via && vu.via >= 0);
        if (is_target(f)) {
          int end;
          const float total = std::min({du + (pu - pbf).norm(), window.distance(pbf), window.around(pbf, end)});
          if (total < best) best = total, best_node = u, best_face = f;
        }
        for (int k = 0; k < 3; ++k) {
          const int other = graph_.halfedge_edge[3 * f + k];
          if (other == e) continue;
          const auto [first, end] = graph_.node_range(other);
          const int count = end - first;
          const int r0 = visit(first, other);
          for (int rn = r0; rn < r0 + count; ++rn) {
            Visit& v = visits_[rn];
            if (v.closed) continue;
            int end;
            const float hop = du + (v.position - pu).norm(), straight = window.distance(v.position),
                        bend = window.around(v.position, end);
            const float d = std::min({hop, straight, bend});
            if (d >= v.dist) continue;
            v.dist = d;
            v.parent = u;
            v.via = f;
            if (straight <= d) {
              window.pass_on(mesh_, origin_, graph_.edge_halfedge[other], v);
            } else if (bend <= d) {  // round A or B, which sees the whole of the other edges of f
              v.source = end == 0 ? window.a : Eigen::Vector3f(window.a + window.length * window.x);
              v.source_dist = end == 0 ? window.to_a : window.to_b, v.lo = 0, v.hi = edge_length(other);
            } else {  // from u itself, likewise
              v.source = pu, v.source_dist = du, v.lo = 0, v.hi = edge_length(other);
            }
            queue.push(key(v), rn);
          }
        }
      }
    }
  }
  if (corridor) {
    for (int f : *corridor) corridor_bits_[f >> 6] = 0;
    for (int f : sources) corridor_bits_[f >> 6] = 0;
    for (int f : targets) corridor_bits_[f >> 6] = 0;
  }
  if (stats) ++stats->searches, stats->visited_nodes += visited;
  if (best_face >= 0) last_length_ = best;

  auto parent = [&](int node) { return visits_[slot(node)].parent; };
  if (best_face >= 0) {
    // Walk back: face nodes contribute their face, links the face they run through.
    strip.push_back(best_face);
    for (int node = best_node; node >= 0; node = parent(node)) {
      if (node < nf) {
        strip.push_back(node);
      } else {
        int faces[2];
        node_faces(mesh_, graph_, node, faces);
        const int f = strip.back();
        // An edge node between the face after it and the face before it in the strip.
        const int before = parent(node) >= 0 ? link_face(node, parent(node)) : -1;
        if (faces[0] != f && faces[1] != f) strip.push_back(faces[0] == before ? faces[1] : faces[0]);
        if (before >= 0) strip.push_back(before);
      }
    }
    // The first node was linked to the source point through a source face.
    {
      int first = best_node;
      while (first >= 0 && parent(first) >= 0) first = parent(first);
      int faces[2];
      if (first >= nf) {
        node_faces(mesh_, graph_, first, faces);
        const int src = std::find(sources.begin(), sources.end(), faces[0]) != sources.end() ? faces[0] : faces[1];
        if (strip.back() != src) strip.push_back(src);
      }
    }
    std::reverse(strip.begin(), strip.end());
    strip.erase(std::unique(strip.begin(), strip.end()), strip.end());
  }
  for (size_t i = 0; i < visits_.size(); ++i) {  // (an edge's records are consecutive)
    const int node = visits_[i].node;
    if (node < nf) {
      face_slot_[node] = -1;
    } else {
      const int e = graph_.edge_of_node(node);
      edge_slot_[e] = -1;
      const auto [first, end] = graph_.node_range(e);
      i += end - first - 1;
    }
  }
  visits_.clear();
  // A long refined search can touch most of the graph; its records are not kept beyond 2 MB.
  if (visits_.capacity() * sizeof(Visit) > (size_t{2} << 20)) visits_ = std::vector<Visit>();
  if (best_face < 0) return false;
  remove_loops(strip, face_slot_);
  return true;
}

}  // namespace splinekit::surface
