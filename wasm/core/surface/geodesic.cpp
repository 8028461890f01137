#include "surface/geodesic.h"

#include "surface/unfold.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

namespace splinekit::surface {

// =================================================================================================
// Phase (i): the refined dual graph and its search
// =================================================================================================

namespace {

// A growable ring buffer: the deque of the SLF/LLL search.
class RingDeque {
 public:
  bool empty() const { return size_ == 0; }
  size_t size() const { return size_; }
  int front() const { return data_[head_]; }
  void clear() { head_ = size_ = 0; }
  void push_back(int x) {
    grow();
    data_[(head_ + size_) & mask_] = x;
    ++size_;
  }
  void push_front(int x) {
    grow();
    head_ = (head_ + mask_) & mask_;
    data_[head_] = x;
    ++size_;
  }
  int pop_front() {
    const int x = data_[head_];
    head_ = (head_ + 1) & mask_;
    --size_;
    return x;
  }

 private:
  void grow() {
    if (size_ < data_.size()) return;
    std::vector<int> next(std::max<size_t>(64, 2 * data_.size()));
    for (size_t i = 0; i < size_; ++i) next[i] = data_[(head_ + i) & mask_];
    data_.swap(next);
    head_ = 0;
    mask_ = data_.size() - 1;
  }
  std::vector<int> data_;
  size_t head_ = 0, size_ = 0, mask_ = 0;
};

bool contains_vertex(const TriMesh& mesh, int face, int v) { return corner_of(mesh, face, v) >= 0; }

// The angle of `face` at its vertex v.
double corner_angle(const TriMesh& mesh, int face, int v) {
  const auto& t = mesh.triangles[face];
  const int k = corner_of(mesh, face, v);
  const Vec3 a = mesh.positions[t[(k + 1) % 3]] - mesh.positions[v], b = mesh.positions[t[(k + 2) % 3]] - mesh.positions[v];
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

// The edge of `face` at its vertex v that a walk around v crosses to keep v on its left (or right).
int edge_around(const TriMesh& mesh, int face, int v, bool keep_left) {
  const int k = corner_of(mesh, face, v);
  return keep_left ? (k + 2) % 3 : k;
}

// Faces that contain a point: its face, the neighbour across the edge it lies on, or its vertex's fan.
void faces_of_point(const TriMesh& mesh, const MeshPoint& p, std::vector<int>& faces) {
  faces.clear();
  const PointLocation where = locate(mesh, p);
  if (where.kind == PointLocation::kVertex) {
    bool closed;
    vertex_fan(mesh, where.index, faces, closed);
    if (std::find(faces.begin(), faces.end(), p.face) == faces.end()) faces.push_back(p.face);
    return;
  }
  faces.push_back(p.face);
  if (where.kind == PointLocation::kEdge && mesh.adjacency[p.face][where.index] >= 0)
    faces.push_back(mesh.adjacency[p.face][where.index]);
}

// Cuts the loops out of a strip: when a face appears twice, the faces between are dropped.
void remove_loops(std::vector<int>& strip, std::vector<int>& slot) {
  size_t out = 0;
  for (size_t i = 0; i < strip.size(); ++i) {
    const int f = strip[i];
    if (slot[f] >= 0) {
      for (size_t j = slot[f] + 1; j < out; ++j) slot[strip[j]] = -1;
      out = slot[f] + 1;
      continue;
    }
    slot[f] = static_cast<int>(out);
    strip[out++] = f;
  }
  strip.resize(out);
  for (int f : strip) slot[f] = -1;
}

}  // namespace

int DualGraph::edge_of_node(int node) const {
  const int local = node - faces;
  if (edge_offsets.empty()) return local / steiner;
  return static_cast<int>(std::upper_bound(edge_offsets.begin(), edge_offsets.end(), local) - edge_offsets.begin()) - 1;
}

GeodesicSolver::GeodesicSolver(const TriMesh& mesh, const ShortestPathOptions& options)
    : mesh_(mesh), options_(options) {
  const int nf = static_cast<int>(mesh.triangles.size());
  graph_.faces = nf;
  graph_.steiner = std::max(1, options.steiner);
  graph_.long_edge = options.long_edge_fraction * mesh.scale;
  graph_.halfedge_edge.assign(3 * static_cast<size_t>(nf), -1);
  std::vector<int> counts;
  bool uniform = true;
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
      const int extra = len > graph_.long_edge ? static_cast<int>(std::ceil(len / graph_.long_edge)) - 1 : 0;
      counts.push_back(std::max(graph_.steiner, extra));
      uniform = uniform && counts.back() == graph_.steiner;
    }
  }
  graph_.edges = static_cast<int>(graph_.edge_halfedge.size());
  if (!uniform) {
    graph_.edge_offsets.assign(1, 0);
    for (int c : counts) graph_.edge_offsets.push_back(graph_.edge_offsets.back() + c);
  }
  slot_.assign(graph_.nodes(), -1);
  centroids_.resize(nf);
  for (int f = 0; f < nf; ++f) {
    const auto& t = mesh.triangles[f];
    centroids_[f] = ((mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]) / 3).cast<float>();
  }
  angle_sums_.assign(mesh.positions.size(), std::numeric_limits<double>::quiet_NaN());
}

size_t GeodesicSolver::bytes() const {
  return (graph_.halfedge_edge.capacity() + graph_.edge_halfedge.capacity() + graph_.edge_offsets.capacity()) * sizeof(int) +
         slot_.capacity() * sizeof(int) + visits_.capacity() * sizeof(Visit) + centroids_.capacity() * sizeof(centroids_[0]) +
         angle_sums_.capacity() * sizeof(double);
}

// Position of graph node `node`: a face centroid, or a point along an edge.
Vec3 GeodesicSolver::node_position(int node) const {
  if (node < graph_.faces) return centroids_[node].cast<double>();
  const int e = graph_.edge_of_node(node);
  const int first = graph_.first_node(e), count = graph_.end_node(e) - first;
  const int h = graph_.edge_halfedge[e];
  const auto& t = mesh_.triangles[h / 3];
  const double s = double(node - first + 1) / (count + 1);
  return (1 - s) * mesh_.positions[t[h % 3]] + s * mesh_.positions[t[(h % 3 + 1) % 3]];
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

int GeodesicSolver::link_face(int a, int b) const {
  int fa[2], fb[2];
  node_faces(mesh_, graph_, a, fa);
  node_faces(mesh_, graph_, b, fb);
  for (int x : fa)
    for (int y : fb)
      if (x >= 0 && x == y) return x;
  return -1;
}

bool GeodesicSolver::initial_strip(const MeshPoint& a, const MeshPoint& b, std::vector<int>& strip, PathStats* stats,
                                   SearchGraph graph) {
  const bool dual = graph == SearchGraph::kDual;
  strip.clear();
  const int nf = graph_.faces;
  static thread_local std::vector<int> sources, targets;
  faces_of_point(mesh_, a, sources);
  faces_of_point(mesh_, b, targets);
  for (int s : sources) {
    if (std::find(targets.begin(), targets.end(), s) != targets.end()) {
      strip.push_back(s);
      return true;
    }
  }
  const Vec3 pa = eval_position(mesh_, a);
  const Vec3 pb = eval_position(mesh_, b);
  const double weight = dual ? options_.dual_heuristic_weight : 1.0;
  static thread_local RingDeque queue;
  queue.clear();
  visits_.clear();
  double key_sum = 0;  // sum of (dist + heuristic) over queued nodes, for LLL
  // The record of a node (made on first touch: its position is looked at many times).
  auto visit = [&](int node) -> Visit& {
    int& slot = slot_[node];
    if (slot < 0) {
      const Vec3 p = node_position(node);
      slot = static_cast<int>(visits_.size());
      visits_.push_back({std::numeric_limits<float>::infinity(), static_cast<float>(weight * (p - pb).norm()), node, -1,
                         p.cast<float>(), false});
    }
    return visits_[slot];
  };
  auto key = [&](const Visit& v) { return v.dist + v.heuristic; };
  // Relaxes `node` from `from`; SLF puts improved nodes at the front or the back of the deque.
  auto relax = [&](int node, int from, float d) {
    Visit& v = visit(node);
    if (d >= v.dist) return;
    if (v.queued) {
      key_sum -= v.dist - d;
    } else {
      key_sum += d + v.heuristic;
      v.queued = true;
      if (!queue.empty() && d + v.heuristic < key(visits_[queue.front()]))
        queue.push_front(slot_[node]);
      else
        queue.push_back(slot_[node]);
    }
    v.dist = d;
    v.parent = from;
  };
  // The nodes of face f: its centroid and the nodes on its edges (but those on `skip_edge`).
  auto for_face_nodes = [&](int f, int skip_edge, auto&& each) {
    each(f);
    if (dual) return;
    for (int k = 0; k < 3; ++k) {
      const int e = graph_.halfedge_edge[3 * f + k];
      if (e == skip_edge) continue;
      for (int n = graph_.first_node(e), end = graph_.end_node(e); n < end; ++n) each(n);
    }
  };
  auto is_target = [&](int f) { return std::find(targets.begin(), targets.end(), f) != targets.end(); };
  // Best arrival into a target face so far: from node, into face, total length.
  int best_node = -1, best_face = -1;
  float best = std::numeric_limits<float>::infinity();

  for (int s : sources)
    for_face_nodes(s, -1, [&](int node) { relax(node, -1, static_cast<float>((visit(node).position.cast<double>() - pa).norm())); });

  int visited = 0;
  while (!queue.empty()) {
    // LLL: nodes whose key exceeds the queue's mean go to the back (the deque holds records).
    const double mean = key_sum / static_cast<double>(queue.size());
    for (size_t moves = 0; moves < queue.size(); ++moves) {
      const int r = queue.front();
      if (key(visits_[r]) <= mean) break;
      queue.pop_front();
      queue.push_back(r);
    }
    const int r = queue.pop_front();
    visits_[r].queued = false;
    key_sum -= key(visits_[r]);
    // A* bound: a node whose key reaches the best arrival cannot improve it (the deque is not a
    // priority queue, so the search drains it instead of stopping at the first such node).
    if (key(visits_[r]) >= best) {
      if (dual) break;
      continue;
    }
    ++visited;
    // (copies: visit() may grow visits_)
    const int u = visits_[r].node;
    const float du = visits_[r].dist, hu = visits_[r].heuristic;
    const Eigen::Vector3f pu = visits_[r].position;
    auto arrive = [&](int f) {
      if (is_target(f) && du + hu < best) best = du + hu, best_node = u, best_face = f;
    };
    auto expand_face = [&](int f, int skip_edge) {
      arrive(f);
      for_face_nodes(f, skip_edge, [&](int node) {
        if (node != u) relax(node, u, du + (visit(node).position - pu).norm());
      });
    };
    if (dual) {
      arrive(u);
      for (int g : mesh_.adjacency[u])
        if (g >= 0) relax(g, u, du + (visit(g).position - pu).norm());
    } else if (u < nf) {
      expand_face(u, -1);
    } else {
      int faces[2];
      node_faces(mesh_, graph_, u, faces);
      const int e = graph_.edge_of_node(u);
      for (int f : faces)
        if (f >= 0) expand_face(f, e);
    }
  }
  if (stats) stats->visited_nodes += visited;

  auto parent = [&](int node) { return visits_[slot_[node]].parent; };
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
  for (const Visit& v : visits_) slot_[v.node] = -1;
  visits_.clear();
  // A long refined search can touch most of the graph; its records are not kept beyond 2 MB.
  if (visits_.capacity() > (size_t{1} << 16)) visits_ = std::vector<Visit>();
  if (best_face < 0) return false;
  remove_loops(strip, slot_);
  return true;
}

// =================================================================================================
// Phases (ii) and (iii): funnel and straightening
// =================================================================================================

namespace {

double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }
// Positive when c is to the left of a -> b.
double orient(const Vec2& a, const Vec2& b, const Vec2& c) { return cross2(b - a, c - a); }

struct Apex {
  Vec2 pos;
  int vertex = -1;   // mesh vertex (-1 for the end points)
  int portal = -1;   // index of the last portal it bounds (-1 for the start; #portals for the end)
  int emitted = -1;  // the portal whose processing made it the apex (the funnel's state from then on
                     // depends on it and the portals after it only)
};

// How a strip differs from one whose funnel path is known (`path`): its portals before `lo` are
// that strip's, and its portals from `hi` on are that strip's portals `shift` further on, moved by
// `motion`.
struct Splice {
  const std::vector<Apex>* path = nullptr;
  int lo = 0, hi = 0, shift = 0;
  PlaneMotion motion;
};

// The funnel algorithm over the portals of an unfolded strip ("simple stupid funnel").
// With a splice, the funnel takes up the known path at its last apex made before `lo` (from there
// on it is in the same state), and once an apex beyond `hi` is one of the known path's, it ends
// with that path's (the same portals follow, moved).
void funnel(const UnfoldedStrip& u, const Vec2& source, const Vec2& target, std::vector<Apex>& apices,
            const Splice* splice = nullptr) {
  const int n = static_cast<int>(u.portals.size());
  apices.clear();
  apices.push_back({source, -1, -1, -1});
  if (splice) {
    const std::vector<Apex>& known = *splice->path;
    size_t m = 0;
    while (m + 2 < known.size() && known[m + 1].emitted < splice->lo) ++m;
    apices.insert(apices.end(), known.begin() + 1, known.begin() + m + 1);
  }
  Vec2 apex = apices.back().pos, left = apex, right = apex;
  int apex_index = apices.back().portal, left_index = apex_index, right_index = apex_index;
  int left_vertex = apices.back().vertex, right_vertex = left_vertex;
  // The known path's apex that the one just made is, past `hi`, or 0.
  auto known_from = [&]() -> size_t {
    const Apex& x = apices.back();
    if (!splice || x.portal < splice->hi || x.vertex < 0) return 0;
    const std::vector<Apex>& known = *splice->path;
    const int at = x.portal + splice->shift;
    const auto y = std::lower_bound(known.begin(), known.end(), at, [](const Apex& a, int p) { return a.portal < p; });
    return y != known.end() && y->portal == at && y->vertex == x.vertex ? static_cast<size_t>(y - known.begin()) : 0;
  };
  auto finish_known = [&](size_t y) {
    const std::vector<Apex>& known = *splice->path;
    for (size_t k = y + 1; k < known.size(); ++k)
      apices.push_back({splice->motion(known[k].pos), known[k].vertex, known[k].portal - splice->shift, known[k].emitted - splice->shift});
    apices.back().pos = target;
  };
  for (int i = apex_index + 1; i <= n; ++i) {
    const Vec2 L = i < n ? u.left(i) : target;
    const Vec2 R = i < n ? u.right(i) : target;
    const int lv = i < n ? u.portals[i].left_vertex : -1;
    const int rv = i < n ? u.portals[i].right_vertex : -1;
    // Right side: tighten when R is left of (or on) apex->right.
    if (orient(apex, right, R) >= 0) {
      if (apex == right || apex == left || orient(apex, left, R) < 0) {
        right = R;
        right_index = i;
        right_vertex = rv;
      } else {
        // R crosses over the left side: the left point becomes the apex.
        apices.push_back({left, left_vertex, left_index, i});
        if (const size_t y = known_from()) return finish_known(y);
        apex = left;
        apex_index = left_index;
        right = left = apex;
        right_index = left_index = apex_index;
        right_vertex = left_vertex;
        i = apex_index;
        continue;
      }
    }
    // Left side: tighten when L is right of (or on) apex->left.
    if (orient(apex, left, L) <= 0) {
      if (apex == left || apex == right || orient(apex, right, L) > 0) {
        left = L;
        left_index = i;
        left_vertex = lv;
      } else {
        apices.push_back({right, right_vertex, right_index, i});
        if (const size_t y = known_from()) return finish_known(y);
        apex = right;
        apex_index = right_index;
        left = right = apex;
        left_index = right_index = apex_index;
        left_vertex = right_vertex;
        i = apex_index;
        continue;
      }
    }
  }
  if (apices.back().pos == target && apices.size() > 1) apices.pop_back();
  apices.push_back({target, -1, n, n});
}

// Turning angle of the path at apex j (0 at the ends).
double turn_at(const std::vector<Apex>& apices, size_t j) {
  if (j == 0 || j + 1 >= apices.size()) return 0;
  const Vec2 a = apices[j].pos - apices[j - 1].pos, b = apices[j + 1].pos - apices[j].pos;
  return std::atan2(std::abs(cross2(a, b)), a.dot(b));
}

// Drops the apices where the funnel's path goes straight on but for rounding (a vertex on the line
// between its neighbours): they would stand in for the real bends next to them.
void drop_straight(std::vector<Apex>& apices) {
  size_t kept = 1;
  for (size_t j = 1; j + 1 < apices.size(); ++j) {
    const Vec2 a = apices[j].pos - apices[kept - 1].pos, b = apices[j + 1].pos - apices[j].pos;
    if (std::abs(cross2(a, b)) > 1e-12 * a.norm() * b.norm() || a.dot(b) < 0) apices[kept++] = apices[j];
  }
  apices[kept++] = apices.back();
  apices.resize(kept);
}

// Lerps on every portal from the funnel's polyline, and the arc length at each point of the path
// (start, crossings, end).
void crossings(const UnfoldedStrip& u, const std::vector<Apex>& apices, std::vector<double>& lerps, std::vector<double>& arc) {
  const int n = static_cast<int>(u.portals.size());
  lerps.resize(n);
  arc.resize(n + 2);
  arc[0] = 0;
  Vec2 prev = apices.front().pos;
  size_t j = 0;
  for (int i = 0; i < n; ++i) {
    while (j + 1 < apices.size() && apices[j + 1].portal < i) ++j;
    const Vec2& q = apices[j].pos;
    const Vec2 d = apices[j + 1].pos - q;
    const Vec2& R = u.right(i);
    const Vec2& L = u.left(i);
    const double den = cross2(d, L - R);
    double s = std::abs(den) > 0 ? cross2(d, q - R) / den : 0.5;
    if (!(s >= 0)) s = 0;
    if (s > 1) s = 1;
    lerps[i] = s;
    const Vec2 at = R + s * (L - R);
    arc[i + 1] = arc[i] + (at - prev).norm();
    prev = at;
  }
  arc[n + 1] = arc[n] + (apices.back().pos - prev).norm();
}

double polyline_length(const std::vector<Apex>& apices) {
  double length = 0;
  for (size_t j = 1; j < apices.size(); ++j) length += (apices[j].pos - apices[j - 1].pos).norm();
  return length;
}

}  // namespace

void GeodesicSolver::straighten(const MeshPoint& a, const MeshPoint& b, std::vector<int>& strip, GeodesicPath& path,
                                PathStats* stats) {
  path.strip = strip;
  point_in_face(mesh_, a, strip.front(), path.start);
  point_in_face(mesh_, b, strip.back(), path.end);
  path.lerps.clear();
  path.arc.clear();
  if (strip.size() == 1) return;
  // Flips keep the strip's first and last faces, so the end points stay where they are.
  const MeshPoint start = path.start, end = path.end;

  // The strip, its unfolding and its funnel path, and the strip being tried with theirs (laid out
  // from the strip's by `apply`).
  static thread_local UnfoldedStrip unfolded, trial_unfolded;
  // (`made`: the funnel's own apices, before those where it goes straight on are dropped)
  static thread_local std::vector<Apex> apices, trial_apices, made, trial_made;
  static thread_local std::vector<int> frozen, trial;
  frozen.clear();
  auto shorten = [&](const UnfoldedStrip& u, std::vector<Apex>& raw, std::vector<Apex>& out, const Splice* splice) {
    funnel(u, u.map(0, start), u.map(static_cast<int>(u.faces.size()) - 1, end), raw, splice);
    out.assign(raw.begin(), raw.end());
    drop_straight(out);
    return polyline_length(out);
  };
  unfold_strip(mesh_, strip, unfolded);
  double length = shorten(unfolded, made, apices, nullptr);
  auto strip_size = [&]() { return static_cast<int>(strip.size()); };

  // The faces of the strip around vertex v, from the face at index `at`.
  auto run_of = [&](int v, int at, int& first, int& last) {
    first = last = std::clamp(at, 0, strip_size() - 1);
    if (!contains_vertex(mesh_, strip[first], v)) return false;
    while (first > 0 && contains_vertex(mesh_, strip[first - 1], v)) --first;
    while (last + 1 < strip_size() && contains_vertex(mesh_, strip[last + 1], v)) ++last;
    return true;
  };
  // Whether the strip holds apex vertex v on its left.
  auto on_left = [&](const Apex& x) {
    return unfolded.portals[std::clamp(x.portal, 0, static_cast<int>(unfolded.portals.size()) - 1)].left_vertex == x.vertex;
  };

  // A change of the strip at apex j: strip[first + 1 .. last - 1] becomes `other`.
  struct Flip {
    int first, last, vertex;
    double turn;
    std::vector<int> other;
    std::vector<std::array<Vec2, 3>> laid;  // a chord's: where its trace laid `other` (the strip's layout)
    bool chain = false, chord = false;
  };
  static thread_local std::vector<Flip> flips;
  size_t used = 0;  // the first `used` flips are this pass's

  constexpr double kPi = 3.14159265358979323846;
  // Whether the path through v, turning by `turn`, is locally shortest there (by v's angle sum,
  // once known: NaN until then).
  auto straight_through = [&](int v, double turn) { return angle_sums_[v] - kPi - turn >= kPi - 1e-9; };
  // Phase (iii)'s flip of apex j (where the path turns by `turn`), or false (and the vertex is
  // frozen) when the path cannot be shortened there: the other side of v is open (a boundary) or
  // spans at least π, i.e. the angle sum θ satisfies θ − (π + turn) ≥ π (the path through v is then
  // locally shortest). `first`..`last`: v's run in the strip.
  auto make_flip = [&](size_t j, double turn, int first, int last, Flip& flip) {
    const int v = apices[j].vertex;
    flip.vertex = v;
    flip.turn = turn;
    flip.chain = flip.chord = false;
    flip.laid.clear();
    if (straight_through(v, turn)) return false;
    const int f0 = strip[first];
    // The run turns around v keeping it on its left or right; the other semi-star the other way.
    const bool run_left = first < last && mesh_.adjacency[f0][edge_around(mesh_, f0, v, true)] == strip[first + 1];
    flip.first = first, flip.last = last;
    flip.other.clear();
    for (int f = f0, steps = 0; steps < 4096; ++steps) {
      f = mesh_.adjacency[f][edge_around(mesh_, f, v, !run_left)];
      if (f < 0) return false;
      if (f == strip[last]) break;
      flip.other.push_back(f);
    }
    double& angle_sum = angle_sums_[v];  // the whole fan: the run and the other side
    if (std::isnan(angle_sum)) {
      angle_sum = 0;
      for (int i = first; i <= last; ++i) angle_sum += corner_angle(mesh_, strip[i], v);
      for (int f : flip.other) angle_sum += corner_angle(mesh_, f, v);
    }
    return !straight_through(v, turn);
  };
  // Zippers. A path that runs along a line of mesh vertices on the wrong side of it bends at one of
  // them, v; flipping v alone moves the bend to the next vertex of the line, one pass per vertex.
  // So the flip of apex j takes in the strip's boundary vertices next to v, on v's side and between
  // the neighbouring apices, that would still block the path with v out of the way (they lie on v's
  // side of the chord between the neighbouring apices), and replaces the strip faces around all of
  // them by the faces on their other side. The pass keeps it only if the path gets shorter;
  // otherwise v gets the single flip from then on (`no_chain`).
  static thread_local std::vector<int> no_chain, pivots;
  no_chain.clear();
  auto extend_chain = [&](size_t j, Flip& flip) {
    const int v = apices[j].vertex, n = static_cast<int>(strip.size());
    if (n < 3 || std::find(no_chain.begin(), no_chain.end(), v) != no_chain.end()) return;
    const Portal& own = unfolded.portals[std::clamp(apices[j].portal, 0, n - 2)];
    const bool left = own.left_vertex == v;
    if (!left && own.right_vertex != v) return;
    auto side_vertex = [&](int i) { return left ? unfolded.portals[i].left_vertex : unfolded.portals[i].right_vertex; };
    const Vec2 &from = apices[j - 1].pos, &to = apices[j + 1].pos;
    const bool v_right = orient(from, to, apices[j].pos) < 0;
    auto blocks = [&](int i) {  // the side vertex of portal i
      const double o = orient(from, to, left ? unfolded.left(i) : unfolded.right(i));
      return v_right ? o < 0 : o > 0;
    };
    int first = flip.first, last = flip.last;
    pivots.clear();
    for (int i = first - 1; i > apices[j - 1].portal && blocks(i);) {  // vertices before v, nearest first
      const int c = side_vertex(i);
      while (i > apices[j - 1].portal + 1 && side_vertex(i - 1) == c) --i;
      pivots.push_back(c);
      first = i--;
    }
    std::reverse(pivots.begin(), pivots.end());  // in strip order
    pivots.push_back(v);
    for (int i = last; i < std::min(n - 1, apices[j + 1].portal) && blocks(i);) {  // vertices after v
      const int c = side_vertex(i);
      while (i + 1 < n - 1 && side_vertex(i + 1) == c) ++i;
      pivots.push_back(c);
      last = ++i;
    }
    if (pivots.size() == 1) return;
    // Around each pivot in turn on the side away from the strip, from strip[first] to strip[last].
    // `entry`: the other end of the edge the walk came through (the edge not to cross back over).
    auto around = [&](int f, int pivot, int entry, int& next_entry) {
      const auto& t = mesh_.triangles[f];
      const int k = corner_of(mesh_, f, pivot);
      if (t[(k + 1) % 3] != entry) return next_entry = t[(k + 1) % 3], mesh_.adjacency[f][k];
      return next_entry = t[(k + 2) % 3], mesh_.adjacency[f][(k + 2) % 3];
    };
    const int p0 = pivots[0];
    int entry = pivots[1];
    if (contains_vertex(mesh_, strip[first + 1], p0)) {
      const Portal& shared = unfolded.portals[first];
      entry = shared.left_vertex == p0 ? shared.right_vertex : shared.left_vertex;
    }
    std::vector<int> other;
    size_t at = 0;
    int f = around(strip[first], p0, entry, entry);
    for (int steps = 0;; ++steps) {
      if (f < 0 || steps > 256) return;
      if (at + 1 == pivots.size()) {
        if (f == strip[last]) break;
      } else if (f == strip[last]) {
        return;
      } else if (contains_vertex(mesh_, f, pivots[at + 1])) {
        other.push_back(f);
        f = around(f, pivots[at + 1], pivots[at], entry);
        ++at;
        continue;
      }
      other.push_back(f);
      f = around(f, pivots[at], entry, entry);
    }
    flip.first = first, flip.last = last;
    flip.other.swap(other);
    flip.chain = true;
  };
  // Chords. A long path first found on the dual graph lies rows of vertices away from the geodesic,
  // and semi-star flips move it across one row at a time. So the flip of apex j rather takes the
  // straight line from the neighbouring apex p to the other one, q, in the plane of the strip, and
  // follows it across the mesh from p, laying each face it enters flat (a straightest geodesic from
  // p aimed at q), until a face holds q. Where the surface between turned the line, it aims once
  // more at where those faces put q, or, when the line passed q without meeting it, at where q
  // projects into the plane of the face where it did (a long chord over a curved region drifts by
  // more than a face); the second walk keeps the first as far as the new line crosses the same
  // edges. The strip then runs around p from its faces there to the line, along the line, and
  // around q (on the side the line passes it) to its faces there. When the line meets a boundary or
  // a vertex, misses q twice, or its faces put q too far for the path to get shorter, the flip is
  // the semi-star (and zipper) instead; so it is from then on for a vertex whose chord did not
  // shorten the path.
  static thread_local std::vector<int> no_chord;
  no_chord.clear();
  // `room`: the strip faces from p's first around p to q's last around q (q_first: its first).
  struct Room {
    int p_first, q_first, q_last;
  };
  auto make_chord = [&](size_t j, const Room& room, Flip& flip) {
    const int n = strip_size();
    const Apex &p = apices[j - 1], &q = apices[j + 1];
    const Vec2 o = p.pos;
    Vec2 d = q.pos - p.pos;
    auto side = [&](const Vec2& c) { return cross2(d, c - o); };  // > 0: left of the line
    // The walk: the faces it entered and where it laid them, how many of them it entered turning
    // around p, and the edge it left each face by along the line.
    static thread_local std::vector<int> other;
    static thread_local std::vector<std::array<Vec2, 3>> laid;
    static thread_local std::vector<int8_t> exits;
    size_t around = 0;
    int first = 0, f = strip[0];
    int on_strip = 0;  // strip index of f while the walk follows the strip (its layout is known), else -1
    std::array<Vec2, 3> cf, cg;
    // Where the walk is on the strip after entering face g from strip face `at` (-1: off it).
    auto follow_strip = [&](int at, int g) { return at >= 0 && at + 1 < n && strip[at + 1] == g ? at + 1 : -1; };
    auto step = [&](int e) {  // into the face across edge e of f
      const int g = mesh_.adjacency[f][e];
      if (g < 0) return false;
      on_strip = follow_strip(on_strip, g);
      if (on_strip >= 0) {
        cf = unfolded.corners[on_strip];
      } else {
        lay_across(mesh_, f, e, cf, cg);
        cf = cg;
      }
      f = g;
      other.push_back(f);
      laid.push_back(cf);
      return true;
    };
    // From p along direction d until a face holds q (the end face for the end point): kReached, and
    // q's place in the plane there. When the line passes q without meeting it, kPassed, and q's
    // place estimated from the face where it did: the point of that face's plane nearest to q, laid
    // with the face (exact for q on the face, off by the surface's turning between them otherwise).
    enum Trace { kFailed, kReached, kPassed };
    Vec2 at;
    auto passed = [&]() {
      const Vec3 x = q.vertex >= 0 ? mesh_.positions[q.vertex] : eval_position(mesh_, end);
      return lay_point(mesh_, f, cf, x, at) ? kPassed : kFailed;
    };
    // Whether the line leaves p through face g laid at c (its corner at p holds the line).
    auto leaves_p = [&](int g, const std::array<Vec2, 3>& c) {
      const int k = corner_of(mesh_, g, p.vertex);
      return side(c[(k + 1) % 3]) < 0 && side(c[(k + 2) % 3]) > 0;
    };
    // Around p, on from its first strip face, to the face whose corner holds the line.
    auto turn_around_p = [&]() {
      other.clear(), laid.clear(), exits.clear();
      first = 0, f = strip[0], on_strip = 0;
      cf = unfolded.corners[0];
      if (p.vertex >= 0) {
        first = room.p_first;
        const bool left = on_left(p);
        f = strip[first];
        cf = unfolded.corners[first];
        on_strip = first;
        for (int steps = 0; !leaves_p(f, cf); ++steps) {
          if (steps > 64 || !step(edge_around(mesh_, f, p.vertex, left)) || f == strip[first]) return false;
        }
      }
      around = other.size();
      return true;
    };
    // Along the line, a face laid at c is left through the edge from a corner on the line's right
    // to one on its left (-1: none, the line meets a corner); the line is past q when both ends of
    // that edge lie beyond q along it.
    auto exit_edge = [&](const std::array<Vec2, 3>& c) {
      const double sides[3] = {side(c[0]), side(c[1]), side(c[2])};
      int e = -1;
      for (int k = 0; k < 3; ++k)
        if (sides[k] < 0 && sides[(k + 1) % 3] > 0) e = k;
      return e;
    };
    auto past_q = [&](const std::array<Vec2, 3>& c, int e) {
      const double reach = 1.05 * d.squaredNorm();
      return (c[e] - o).dot(d) > reach && (c[(e + 1) % 3] - o).dot(d) > reach;
    };
    // Along the line from f on.
    auto along = [&]() {
      for (size_t steps = exits.size(); q.vertex >= 0 ? !contains_vertex(mesh_, f, q.vertex) : f != strip.back(); ++steps) {
        const int e = exit_edge(cf);
        if (e < 0 || steps > 4 * static_cast<size_t>(n)) return kFailed;
        if (past_q(cf, e)) return passed();
        exits.push_back(static_cast<int8_t>(e));
        if (!step(e)) return kFailed;
      }
      at = q.vertex >= 0 ? cf[corner_of(mesh_, f, q.vertex)] : on_face(cf, end);
      return kReached;
    };
    // The walk along a new d: as far as it takes the same way as the last one (the same turn around
    // p, the same exits from the same faces, laid alike), the last one's; on from where they part.
    auto walk_again = [&]() {
      const std::array<Vec2, 3>* c = &unfolded.corners[first];
      size_t s = 0;
      if (p.vertex >= 0) {
        for (int g = strip[first];; ++s) {
          const bool holds = leaves_p(g, *c);
          if (s == around && holds) break;
          if (s == around || holds) return turn_around_p() ? along() : kFailed;
          g = other[s], c = &laid[s];
        }
      }
      size_t m = 0;
      for (; m < exits.size() && exit_edge(*c) == exits[m] && !past_q(*c, exits[m]); ++m) c = &laid[s++];
      cf = *c;
      other.resize(s), laid.resize(s), exits.resize(m);
      f = s == 0 ? strip[first] : other[s - 1];
      on_strip = first;
      for (int g : other) on_strip = follow_strip(on_strip, g);
      return along();
    };
    Trace traced = turn_around_p() ? along() : kFailed;
    // The surface between turned the line: aim again where the line's faces put q (once).
    if (traced == kPassed || (traced == kReached && std::abs(cross2(d, at - o)) > 1e-3 * d.squaredNorm())) {
      if (!((at - o).squaredNorm() > 0)) return false;
      d = at - o;
      traced = walk_again();
    }
    if (traced != kReached) return false;
    // The path from p to q through the line's faces is at least |at - o| long, so the chord cannot
    // help unless that beats the way by v.
    if ((at - o).norm() >= (apices[j].pos - p.pos).norm() + (q.pos - apices[j].pos).norm()) return false;
    int last = n - 1;
    if (q.vertex >= 0) {  // around q, on the side the line passes it, to its strip faces
      const bool left = side(at) > 0;
      for (int steps = 0;; ++steps) {
        int m = room.q_first;
        while (m <= room.q_last && strip[m] != f) ++m;
        if (m <= room.q_last) {
          last = m;
          break;
        }
        if (steps > 64 || !step(edge_around(mesh_, f, q.vertex, left))) return false;
      }
    }
    if (!other.empty() && other.back() == strip[last]) other.pop_back(), laid.pop_back();
    if (last <= first) return false;
    flip.first = first, flip.last = last;
    flip.other.swap(other);  // (the walk's buffers are scratch: the next walk clears them)
    flip.laid.swap(laid);
    flip.chord = true;
    return true;
  };

  // The strip with `chosen` made (in strip order), and its layout: the strip's own between the
  // changes, each piece moved rigidly to where the change before it leaves it; a chord's faces where
  // its trace laid them (moved likewise); other faces laid anew. `splice` tells the funnel where
  // the strips agree (none when a loop had to be cut).
  auto apply = [&](const std::vector<const Flip*>& chosen, std::vector<int>& out, UnfoldedStrip& u, Splice& splice) {
    u.faces.clear(), u.corners.clear(), u.portals.clear();
    splice.path = &made;
    splice.lo = chosen.front()->first;
    append_moved(u, unfolded, 0, chosen.front()->first + 1, PlaneMotion{});
    PlaneMotion moved;
    for (size_t i = 0; i < chosen.size(); ++i) {
      const Flip& f = *chosen[i];
      if (f.chord) {
        const size_t joint = u.faces.size();
        for (size_t k = 0; k < f.other.size(); ++k) append_face(mesh_, u, f.other[k], moved(f.laid[k]));
        join(mesh_, u, joint);
      } else {
        for (int face : f.other) append_laid(mesh_, u, face);
      }
      append_laid(mesh_, u, strip[f.last]);
      moved = PlaneMotion::between(unfolded.corners[f.last], u.corners.back());
      splice.hi = static_cast<int>(u.faces.size()) - 1;
      splice.shift = f.last - splice.hi;
      splice.motion = moved;
      const size_t next = i + 1 < chosen.size() ? chosen[i + 1]->first + 1 : strip.size(), joint = u.faces.size();
      append_moved(u, unfolded, f.last + 1, next, moved);
      join(mesh_, u, joint);
    }
    out.assign(u.faces.begin(), u.faces.end());
    // A new face may also be one the strip keeps elsewhere (or another flip's): then the strip has a
    // loop to cut, and the faces after it are laid anew.
    constexpr int kNew = -2;
    size_t added = 0, seen = 0;
    bool repeated = false;
    for (const Flip* f : chosen)
      for (int face : f->other) repeated |= slot_[face] == kNew, slot_[face] = kNew, ++added;
    for (int face : out) seen += slot_[face] == kNew;
    for (const Flip* f : chosen)
      for (int face : f->other) slot_[face] = -1;
    if (repeated || seen != added) {
      splice.path = nullptr;
      remove_loops(out, slot_);
      unfold_strip(mesh_, out, u, &unfolded);
    }
  };

  static thread_local std::vector<std::pair<double, size_t>> order;
  static thread_local std::vector<const Flip*> chosen;
  auto is_frozen = [&](int v) { return std::find(frozen.begin(), frozen.end(), v) != frozen.end(); };
  for (int pass = 0; options_.straighten && pass < options_.max_flips; ++pass) {
    // Every removable reflex vertex, largest turn first, with runs that do not touch each other.
    order.clear();
    for (size_t j = 1; j + 1 < apices.size(); ++j) {
      if (apices[j].vertex < 0 || is_frozen(apices[j].vertex)) continue;
      const double turn = turn_at(apices, j);
      if (turn > 1e-9) order.emplace_back(-turn, j);
    }
    if (order.empty()) break;
    std::sort(order.begin(), order.end());
    used = 0;
    auto overlaps = [&](int first, int last) {
      return std::any_of(flips.begin(), flips.begin() + used, [&](const Flip& f) { return first <= f.last + 1 && f.first <= last + 1; });
    };
    for (const auto& [neg_turn, j] : order) {
      // A vertex whose faces a flip of this pass already changes cannot flip in it; it is only
      // frozen (as make_flip would) if the path through it is locally shortest.
      int run_first, run_last;
      const int v = apices[j].vertex;
      const bool in_strip = run_of(v, apices[j].portal, run_first, run_last);
      const bool blocked = in_strip && used > 0 && overlaps(run_first, run_last);
      if (blocked && !std::isnan(angle_sums_[v])) {
        if (straight_through(v, -neg_turn)) {
          frozen.push_back(v);
          if (stats) ++stats->frozen;
        }
        continue;
      }
      if (used == flips.size()) flips.emplace_back();
      Flip& flip = flips[used];
      if (!in_strip || !make_flip(j, -neg_turn, run_first, run_last, flip)) {
        frozen.push_back(apices[j].vertex);
        if (stats) ++stats->frozen;
        continue;
      }
      if (blocked) continue;
      // A chord spans the faces around the neighbouring apices: look for room before tracing it.
      Room room{0, strip_size() - 1, strip_size() - 1};
      int unused;
      const bool fits = options_.chords && -neg_turn > options_.chord_min_turn &&
                        (apices[j - 1].vertex < 0 || run_of(apices[j - 1].vertex, apices[j - 1].portal, room.p_first, unused)) &&
                        (apices[j + 1].vertex < 0 || run_of(apices[j + 1].vertex, apices[j + 1].portal, room.q_first, room.q_last)) &&
                        !overlaps(room.p_first, room.q_last);
      if (!fits || std::find(no_chord.begin(), no_chord.end(), flip.vertex) != no_chord.end() || !make_chord(j, room, flip))
        extend_chain(j, flip);
      if (!overlaps(flip.first, flip.last)) ++used;
    }
    if (used == 0) continue;  // all frozen this pass; the next pass finds nothing new
    chosen.clear();
    for (size_t i = 0; i < used; ++i) chosen.push_back(&flips[i]);
    std::sort(chosen.begin(), chosen.end(), [](const Flip* x, const Flip* y) { return x->first < y->first; });
    Splice splice;
    apply(chosen, trial, trial_unfolded, splice);
    double trial_length = shorten(trial_unfolded, trial_made, trial_apices, splice.path ? &splice : nullptr);
    if (!(trial_length < length - 1e-12 * mesh_.scale) && chosen.size() > 1) {
      // Together they did not shorten the path: fall back to the largest turn alone.
      const Flip* best = *std::max_element(chosen.begin(), chosen.end(), [](const Flip* x, const Flip* y) { return x->turn < y->turn; });
      chosen.assign(1, best);
      apply(chosen, trial, trial_unfolded, splice);
      trial_length = shorten(trial_unfolded, trial_made, trial_apices, splice.path ? &splice : nullptr);
    }
    if (trial_length < length - 1e-12 * mesh_.scale) {
      strip.swap(trial);
      std::swap(unfolded, trial_unfolded);
      apices.swap(trial_apices);
      made.swap(trial_made);
      length = trial_length;
      if (stats) stats->flips += static_cast<int>(chosen.size());
    } else {
      for (const Flip* f : chosen) {
        if (f->chord) {
          no_chord.push_back(f->vertex);
        } else if (f->chain) {
          no_chain.push_back(f->vertex);
        } else {
          frozen.push_back(f->vertex);
          if (stats) ++stats->frozen;
        }
      }
    }
  }
  // Crossings of the final strip.
  crossings(unfolded, apices, path.lerps, path.arc);
  path.strip = strip;
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
  static thread_local std::vector<int> strip;
  if (!initial_strip(a, b, strip, stats, graph)) {
    path = GeodesicPath{a, b, {}, {}, {}};
    return false;
  }
  straighten(a, b, strip, path, stats);
  return true;
}

namespace {

// Appends to `strip` (ending at a face that holds p) the faces from there to `face`, which also holds
// p: nothing when it is the same face, `face` when adjacent, else the way around p's vertex that
// spans the smaller angle (the other way the path would wrap around the vertex's far side, which on
// a cone such as a cube's corner straightens into a different, longer geodesic).
bool walk_to(const TriMesh& mesh, const MeshPoint& p, int face, std::vector<int>& strip) {
  const int from = strip.back();
  if (from == face) return true;
  if (edge_to(mesh, from, face) >= 0) {
    strip.push_back(face);
    return true;
  }
  MeshPoint on_from;
  if (!point_in_face(mesh, p, from, on_from)) return false;
  const PointLocation where = locate(mesh, on_from);
  if (where.kind != PointLocation::kVertex) return false;
  static thread_local std::vector<int> fan;
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

bool GeodesicSolver::straighten_through(const std::vector<GeodesicPath>& pieces, GeodesicPath& path, PathStats* stats) {
  static thread_local std::vector<int> strip;
  strip.clear();
  for (const GeodesicPath& piece : pieces) {
    if (piece.strip.empty()) return false;
    if (strip.empty()) {
      strip.push_back(piece.strip.front());
    } else if (!walk_to(mesh_, piece.start, piece.strip.front(), strip)) {
      return false;
    }
    strip.insert(strip.end(), piece.strip.begin() + 1, piece.strip.end());
  }
  remove_loops(strip, slot_);
  straighten(pieces.front().start, pieces.back().end, strip, path, stats);
  return true;
}

// =================================================================================================
// Paths
// =================================================================================================

namespace {

// Crossing i of a path as weights on face strip[i + side] (side 0: its own face, 1: the next one).
MeshPoint crossing_point(const TriMesh& mesh, const GeodesicPath& path, size_t i, int side) {
  const int f = path.strip[i];
  const int g = path.strip[i + 1];
  const int k = edge_to(mesh, f, g);
  const double l = path.lerps[i];
  Eigen::Vector3d w = Eigen::Vector3d::Zero();
  if (side == 0) {
    w[k] = 1 - l;
    w[(k + 1) % 3] = l;
    return from_weights(f, w);
  }
  w[corner_of(mesh, g, mesh.triangles[f][k])] = 1 - l;
  w[corner_of(mesh, g, mesh.triangles[f][(k + 1) % 3])] = l;
  return from_weights(g, w);
}

// Point j of the path (0: start, 1..n-1: crossings, n: end) expressed on strip[j] (or the last face).
MeshPoint point_on_own_face(const TriMesh& mesh, const GeodesicPath& path, size_t j) {
  if (j == 0) return path.start;
  if (j > path.lerps.size()) return path.end;
  return crossing_point(mesh, path, j - 1, 1);
}
// Point j+1 expressed on strip[j].
MeshPoint next_point_on_face(const TriMesh& mesh, const GeodesicPath& path, size_t j) {
  if (j >= path.lerps.size()) return path.end;
  return crossing_point(mesh, path, j, 0);
}

}  // namespace

void path_points(const TriMesh& mesh, const GeodesicPath& path, std::vector<MeshPoint>& points) {
  points.clear();
  points.push_back(path.start);
  for (size_t i = 0; i < path.lerps.size(); ++i) points.push_back(crossing_point(mesh, path, i, 0));
  points.push_back(path.end);
}

void path_positions(const TriMesh& mesh, const GeodesicPath& path, std::vector<Vec3>& positions) {
  positions.clear();
  positions.push_back(eval_position(mesh, path.start));
  for (size_t i = 0; i < path.lerps.size(); ++i) positions.push_back(eval_position(mesh, crossing_point(mesh, path, i, 0)));
  positions.push_back(eval_position(mesh, path.end));
}

double path_length(const TriMesh& mesh, const GeodesicPath& path) {
  Vec3 prev = eval_position(mesh, path.start);
  double length = 0;
  for (size_t i = 0; i < path.lerps.size(); ++i) {
    const Vec3 p = eval_position(mesh, crossing_point(mesh, path, i, 0));
    length += (p - prev).norm();
    prev = p;
  }
  return length + (eval_position(mesh, path.end) - prev).norm();
}

namespace {

// The arc length of a path at each of its points (start, crossings, end): the path's own, or measured
// into `at`.
const std::vector<double>& arc_lengths(const TriMesh& mesh, const GeodesicPath& path, std::vector<double>& at) {
  if (path.arc.size() == path.lerps.size() + 2) return path.arc;
  static thread_local std::vector<Vec3> positions;
  path_positions(mesh, path, positions);
  at.resize(positions.size());
  at[0] = 0;
  for (size_t j = 1; j < positions.size(); ++j) at[j] = at[j - 1] + (positions[j] - positions[j - 1]).norm();
  return at;
}

// Locates arc-length fraction t: segment j (between points j and j+1, on face strip[j]) and the
// fraction within it.
void locate_fraction(const std::vector<double>& at, double t, size_t& segment, double& alpha) {
  const size_t segments = at.size() - 1;
  const double target = std::clamp(t, 0.0, 1.0) * at.back();
  for (size_t j = 0; j < segments; ++j) {
    const double len = at[j + 1] - at[j];
    if (at[j + 1] >= target && len > 0) {
      segment = j;
      alpha = std::clamp((target - at[j]) / len, 0.0, 1.0);
      return;
    }
  }
  segment = segments - 1;
  alpha = 1;
}

MeshPoint lerp_on_segment(const TriMesh& mesh, const GeodesicPath& path, size_t j, double alpha) {
  const MeshPoint p = point_on_own_face(mesh, path, j);
  const MeshPoint q = next_point_on_face(mesh, path, j);
  return {p.face, (1 - alpha) * p.uv + alpha * q.uv};
}

}  // namespace

MeshPoint eval_path(const TriMesh& mesh, const GeodesicPath& path, double t) {
  if (path.strip.empty()) return path.start;
  static thread_local std::vector<double> scratch;
  const std::vector<double>& at = arc_lengths(mesh, path, scratch);
  size_t j;
  double alpha;
  locate_fraction(at, t, j, alpha);
  return lerp_on_segment(mesh, path, j, alpha);
}

GeodesicPath sub_path(const TriMesh& mesh, const GeodesicPath& path, double t0, double t1) {
  if (path.strip.empty()) return path;
  static thread_local std::vector<double> scratch;
  const std::vector<double>& at = arc_lengths(mesh, path, scratch);
  size_t j0, j1;
  double a0, a1;
  locate_fraction(at, t0, j0, a0);
  locate_fraction(at, t1, j1, a1);
  GeodesicPath out;
  out.start = lerp_on_segment(mesh, path, j0, a0);
  out.end = lerp_on_segment(mesh, path, j1, a1);
  out.strip.assign(path.strip.begin() + j0, path.strip.begin() + j1 + 1);
  out.lerps.assign(path.lerps.begin() + j0, path.lerps.begin() + j1);
  // Its arc lengths: the path's from its start point on.
  const double s0 = at[j0] + a0 * (at[j0 + 1] - at[j0]), s1 = at[j1] + a1 * (at[j1 + 1] - at[j1]);
  out.arc.resize(out.lerps.size() + 2);
  out.arc[0] = 0;
  for (size_t k = 1; k <= out.lerps.size(); ++k) out.arc[k] = at[j0 + k] - s0;
  out.arc.back() = std::max(s1 - s0, out.arc[out.lerps.size()]);
  return out;
}

GeodesicPath reversed(const TriMesh&, const GeodesicPath& path) {
  GeodesicPath out;
  out.start = path.end;
  out.end = path.start;
  out.strip.assign(path.strip.rbegin(), path.strip.rend());
  out.lerps.resize(path.lerps.size());
  for (size_t i = 0; i < path.lerps.size(); ++i) out.lerps[i] = 1 - path.lerps[path.lerps.size() - 1 - i];
  if (!path.arc.empty()) {
    out.arc.resize(path.arc.size());
    const double total = path.arc.back();
    for (size_t k = 0; k < path.arc.size(); ++k) out.arc[k] = total - path.arc[path.arc.size() - 1 - k];
  }
  return out;
}

Tangent start_tangent(const TriMesh& mesh, const GeodesicPath& path) {
  if (path.strip.empty()) return {path.start.face, Vec3::Zero()};
  const Vec3 p0 = eval_position(mesh, path.start);
  const double eps = 1e-12 * mesh.scale;
  for (size_t j = 0; j + 1 < path.strip.size() + 1; ++j) {
    const Vec3 q = eval_position(mesh, next_point_on_face(mesh, path, j));
    const Vec3 d = q - p0;
    if (d.norm() > eps) return {path.strip[j], d.normalized()};
  }
  return {path.start.face, Vec3::Zero()};
}

Tangent end_tangent(const TriMesh& mesh, const GeodesicPath& path) {
  if (path.strip.empty()) return {path.end.face, Vec3::Zero()};
  const Vec3 p1 = eval_position(mesh, path.end);
  const double eps = 1e-12 * mesh.scale;
  for (size_t j = path.strip.size(); j-- > 0;) {
    const Vec3 q = eval_position(mesh, point_on_own_face(mesh, path, j));
    const Vec3 d = p1 - q;
    if (d.norm() > eps) return {path.strip[j], d.normalized()};
  }
  return {path.end.face, Vec3::Zero()};
}

}  // namespace splinekit::surface
