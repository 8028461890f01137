#include "surface/dual_search.h"

#include "surface/path.h"

#include <algorithm>
#include <cmath>
#include <limits>

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

int DualGraph::edge_of_node(int node) const {
  const int local = node - faces;
  if (long_edges.empty()) return local / steiner;
  // The last long edge whose nodes start at or before `local` (long edge i starts at
  // long_edges[i]·steiner + long_extra[i]), then the ordinary edges after it.
  int lo = 0, hi = static_cast<int>(long_edges.size());
  while (lo < hi) {
    const int mid = (lo + hi) / 2;
    if (long_edges[mid] * steiner + long_extra[mid] <= local)
      lo = mid + 1;
    else
      hi = mid;
  }
  if (lo == 0) return local / steiner;
  const int i = lo - 1, first = long_edges[i] * steiner + long_extra[i];
  const int end = first + steiner + long_extra[i + 1] - long_extra[i];
  return local < end ? long_edges[i] : long_edges[i] + 1 + (local - end) / steiner;
}

DualSearch::DualSearch(const TriMesh& mesh, const ShortestPathOptions& options)
    : mesh_(mesh),
      dual_heuristic_weight_(options.dual_heuristic_weight),
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
      const int extra = len > graph_.long_edge ? static_cast<int>(std::ceil(len / graph_.long_edge)) - 1 : 0;
      if (extra > graph_.steiner) {
        if (graph_.long_extra.empty()) graph_.long_extra.push_back(0);
        graph_.long_edges.push_back(static_cast<int>(graph_.edge_halfedge.size()) - 1);
        graph_.long_extra.push_back(graph_.long_extra.back() + extra - graph_.steiner);
      }
    }
  }
  graph_.edges = static_cast<int>(graph_.edge_halfedge.size());
  graph_.long_edges.shrink_to_fit();
  graph_.long_extra.shrink_to_fit();
  face_slot_.assign(nf, -1);
  edge_slot_.assign(graph_.edges, -1);
  centroids_.resize(nf);
  for (int f = 0; f < nf; ++f) {
    const auto& t = mesh.triangles[f];
    centroids_[f] = ((mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]) / 3).cast<float>();
  }
  if (nf >= options.landmark_min_faces) landmarks_ = Landmarks(mesh, centroids_, options.landmarks);
}

size_t DualSearch::bytes() const {
  return (graph_.halfedge_edge.capacity() + graph_.edge_halfedge.capacity() + graph_.long_edges.capacity() +
          graph_.long_extra.capacity()) *
             sizeof(int) +
         (face_slot_.capacity() + edge_slot_.capacity()) * sizeof(int) + visits_.capacity() * sizeof(Visit) +
         centroids_.capacity() * sizeof(centroids_[0]) + landmarks_.bytes();
}

// Position of graph node `node` (on edge e, -1 for a face node): a face centroid, or a point along an edge.
Vec3 DualSearch::node_position(int node, int e) const {
  if (node < graph_.faces) return centroids_[node].cast<double>();
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

int DualSearch::link_face(int a, int b) const {
  int fa[2], fb[2];
  node_faces(mesh_, graph_, a, fa);
  node_faces(mesh_, graph_, b, fb);
  for (int x : fa)
    for (int y : fb)
      if (x >= 0 && x == y) return x;
  return -1;
}

bool DualSearch::initial_strip(const MeshPoint& a, const MeshPoint& b, std::vector<int>& strip, PathStats* stats,
                               SearchGraph graph) {
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
  const Vec3 pa = eval_position(mesh_, a);
  const Vec3 pb = eval_position(mesh_, b);
  const Eigen::Vector3f pbf = pb.cast<float>();
  const double weight = dual ? dual_heuristic_weight_ : 1.0;
  // The landmark term (landmarks.h): admissible on the dual graph; scaled down on the refined one.
  const double landmark_weight = dual ? landmark_weight_ : refined_landmark_scale_;
  // (A landmark term of weight 0, the refined search's default, is not computed at all.)
  const bool use_landmarks = !landmarks_.empty() && landmark_weight > 0;
  if (use_landmarks) landmarks_.set_target(targets.data(), static_cast<int>(targets.size()));
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
        visits_.push_back(
            {std::numeric_limits<float>::infinity(), heuristic(p, node), node, -1, p.cast<float>(), false});
      }
      return slot;
    }
    const int first = graph_.first_node(e);
    int& slot = edge_slot_[e];
    if (slot < 0) {
      slot = static_cast<int>(visits_.size());
      const int f = graph_.edge_halfedge[e] / 3;
      for (int n = first, end = graph_.end_node(e); n < end; ++n) {
        const Vec3 p = node_position(n, e);
        visits_.push_back({std::numeric_limits<float>::infinity(), heuristic(p, f), n, -1, p.cast<float>(), false});
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
  // Relaxes every node of edge e likewise: the edge's records are consecutive (most of the refined
  // search's links: an edge node's expansion relaxes two edges of each of its two faces).
  auto relax_edge = [&](int e, int from, const Eigen::Vector3f& at, float d_from) {
    const int first = graph_.first_node(e), count = graph_.end_node(e) - first;
    const int r0 = visit(first, e);
    for (int r = r0; r < r0 + count; ++r) relax_record(r, from, at, d_from);
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
      for (int n = graph_.first_node(e), end = graph_.end_node(e); n < end; ++n) each(n, e);
    }
  };
  auto is_target = [&](int f) { return std::find(targets.begin(), targets.end(), f) != targets.end(); };
  // Best arrival into a target face so far: from node, into face, total length.
  int best_node = -1, best_face = -1;
  float best = std::numeric_limits<float>::infinity();

  const Eigen::Vector3f paf = pa.cast<float>();
  for (int s : sources) for_face_nodes(s, -1, [&](int node, int e) { relax(node, e, -1, paf, 0.f); });

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
    auto expand_face = [&](int f, int skip_edge) {
      arrive(f);
      for_face_nodes(f, skip_edge, [&](int node, int e) {
        if (node != u) relax(node, e, u, pu, du);
      });
    };
    if (dual) {
      arrive(u);
      for (int g : mesh_.adjacency[u])
        if (g >= 0) relax(g, -1, u, pu, du);
    } else if (u < nf) {
      expand_face(u, -1);
    } else {
      int faces[2];
      node_faces(mesh_, graph_, u, faces);
      const int e = graph_.edge_of_node(u);
      for (int f : faces) {
        if (f < 0) continue;
        arrive(f);
        for (int k = 0; k < 3; ++k) {
          const int other = graph_.halfedge_edge[3 * f + k];
          if (other != e) relax_edge(other, u, pu, du);
        }
      }
    }
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
      i += graph_.end_node(e) - graph_.first_node(e) - 1;
    }
  }
  visits_.clear();
  // A long refined search can touch most of the graph; its records are not kept beyond 2 MB.
  if (visits_.capacity() > (size_t{1} << 16)) visits_ = std::vector<Visit>();
  if (best_face < 0) return false;
  remove_loops(strip, face_slot_);
  return true;
}

}  // namespace splinekit::surface
