#include "surface/coarse_guide.h"

#include "surface/geodesic.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace splinekit::surface {

namespace {

// How many fine faces nearest_kept walks before it gives up (a decimation to a sixteenth keeps a
// vertex within a few faces of every face; a sliver-strewn one within a few dozen).
constexpr size_t kMaxWalk = 4096;

}  // namespace

MeshStatus CoarseGuide::build(const TriMesh& fine, const int* triangles, int count, const ShortestPathOptions& options,
                              std::unique_ptr<CoarseGuide>& guide, std::string& error) {
  const int file_vertices = static_cast<int>(fine.mesh_vertex.size());
  if (count <= 0) {
    error = "the coarse mesh has no faces";
    return MeshStatus::kInvalidInput;
  }
  // The coarse file: the fine mesh vertices the triangles use, in order of first use.
  std::vector<int> coarse_file(fine.positions.size(), -1), fine_vertex;
  std::vector<double> positions;
  std::vector<int> faces(3 * static_cast<size_t>(count));
  for (size_t i = 0; i < faces.size(); ++i) {
    const int v = triangles[i];
    if (v < 0 || v >= file_vertices) {
      error = "coarse mesh vertex index " + std::to_string(v) + " is out of range (the mesh has " +
              std::to_string(file_vertices) + " vertices)";
      return MeshStatus::kInvalidInput;
    }
    const int m = fine.mesh_vertex[v];
    if (m < 0) {
      error = "coarse mesh vertex " + std::to_string(v) + " is not a vertex of the mesh's faces";
      return MeshStatus::kInvalidInput;
    }
    if (coarse_file[m] < 0) {
      coarse_file[m] = static_cast<int>(fine_vertex.size());
      fine_vertex.push_back(m);
      positions.insert(positions.end(), fine.positions[m].data(), fine.positions[m].data() + 3);
    }
    faces[i] = coarse_file[m];
  }
  TriMesh coarse;
  if (build_mesh(positions.data(), static_cast<int>(fine_vertex.size()), faces.data(), count, coarse, error) !=
      MeshStatus::kOk) {
    error = "the coarse mesh: " + error;
    return MeshStatus::kInvalidInput;
  }
  // Fine vertex -> coarse mesh vertex (a fine vertex split by the repairs keeps one of its copies).
  std::vector<int> coarse_of_fine(fine.positions.size(), -1);
  // And back: every coarse vertex's fine one (the copies of a split one, the same).
  std::vector<int> fine_of_coarse(coarse.file_vertex.size());
  for (size_t c = 0; c < coarse.file_vertex.size(); ++c) {
    fine_of_coarse[c] = fine_vertex[coarse.file_vertex[c]];
    coarse_of_fine[fine_of_coarse[c]] = int(c);
  }
  guide.reset(new CoarseGuide(fine, std::move(coarse), std::move(coarse_of_fine), std::move(fine_of_coarse), options));
  return MeshStatus::kOk;
}

CoarseGuide::CoarseGuide(const TriMesh& fine, TriMesh coarse, std::vector<int> coarse_of_fine,
                         std::vector<int> fine_of_coarse, const ShortestPathOptions& options)
    : fine_(fine),
      coarse_(std::move(coarse)),
      coarse_of_fine_(std::move(coarse_of_fine)),
      fine_of_coarse_(std::move(fine_of_coarse)) {
  ShortestPathOptions own = options;
  own.coarse_guide_faces = 0;  // (no guide of its own)
  // The coarse search exact on its dual graph (A* with admissible terms), not greedy: the guide is
  // small, and its path decides the side of a limb or turn the fine path keeps to (2026-12-05, 30
  // random curves, against weight 3: the coil's 1.05x the time, the folded body's 1.18x, the knotted
  // tube's 1.02x; curves -0.09%, -0.49% and -0.13% in total length).
  own.dual_heuristic_weight = 1, own.landmark_weight = 1, own.dual_stretch_weight = 0;
  own.refined_landmark_share = 0;  // (its paths are kDual ones)
  // Landmarks on every guide component of 1024 faces or more (a sixteenth of the mesh's threshold):
  // without them the exact search on the knotted tube's 9k-face guide flooded 25 times its path's
  // faces (2026-12-05, 40 random curves, native: knotted tube 426 -> 382 ms, nefertiti 96 -> 88 ms,
  // guide nodes expanded 3.1 and 1.9 times fewer; 4 landmarks cost 0.5 bytes per mesh face).
  own.landmark_min_faces = 1024;
  // One search per path: the search from the other end and the landmark descent make up for a greedy
  // strip's dependence on where it starts, and the exact search's strip is the dual graph's shortest
  // whichever end it starts from (2026-12-05, native, 40 random curves, interleaved: the coil's guide
  // paths of 512 faces or more searched twice, its curves 0.925x the time without, the same curves;
  // the other meshes' guide paths are shorter, unchanged).
  own.dual_reverse_search_faces = 0, own.landmark_descent = false;
  solver_ = std::make_unique<GeodesicSolver>(coarse_, own);
  for (const auto& t : coarse_.triangles)
    for (int k = 0; k < 3; ++k) mean_edge_ += (coarse_.positions[t[(k + 1) % 3]] - coarse_.positions[t[k]]).norm();
  mean_edge_ /= 3.0 * std::max<size_t>(1, coarse_.triangles.size());
  // Long thin faces: the median of (longest edge / shortest edge) over up to 4096 faces.
  std::vector<double> aspect;
  const size_t nf = fine_.triangles.size(), step = std::max<size_t>(1, nf / 4096);
  for (size_t f = 0; f < nf; f += step) {
    const auto& t = fine_.triangles[f];
    double lo = std::numeric_limits<double>::infinity(), hi = 0;
    for (int k = 0; k < 3; ++k) {
      const double e = (fine_.positions[t[(k + 1) % 3]] - fine_.positions[t[k]]).norm();
      lo = std::min(lo, e), hi = std::max(hi, e);
    }
    if (lo > 0) aspect.push_back(hi / lo);
  }
  if (!aspect.empty()) {
    std::nth_element(aspect.begin(), aspect.begin() + aspect.size() / 2, aspect.end());
    walks_ = options.guide_walk_aspect > 0 && aspect[aspect.size() / 2] > options.guide_walk_aspect;
  }
}

CoarseGuide::~CoarseGuide() = default;

const Landmarks& CoarseGuide::landmarks() const { return solver_->landmarks(); }

size_t CoarseGuide::bytes() const {
  return mesh_bytes(coarse_) + solver_->bytes() +
         (coarse_of_fine_.capacity() + fine_of_coarse_.capacity()) * sizeof(int) +
         (from_a_.capacity() + from_b_.capacity()) * sizeof(double);
}

int CoarseGuide::nearest_kept(const MeshPoint& p) {
  // Breadth first over fine faces from p's; the first ring that holds a kept corner gives the kept
  // vertex nearest p in space among its faces.
  const Vec3 x = eval_position(fine_, p);
  queue_.assign(1, p.face);
  int best = -1;
  double best_d = std::numeric_limits<double>::infinity();
  for (size_t begin = 0; begin < queue_.size() && queue_.size() < kMaxWalk;) {
    const size_t end = queue_.size();
    for (size_t i = begin; i < end; ++i)
      for (int v : fine_.triangles[queue_[i]])
        if (coarse_of_fine_[v] >= 0 && (fine_.positions[v] - x).squaredNorm() < best_d)
          best_d = (fine_.positions[v] - x).squaredNorm(), best = coarse_of_fine_[v];
    if (best >= 0) return best;
    for (size_t i = begin; i < end; ++i)
      for (int g : fine_.adjacency[queue_[i]])
        if (g >= 0 && std::find(queue_.begin(), queue_.end(), g) == queue_.end()) queue_.push_back(g);
    begin = end;
  }
  return -1;
}

bool CoarseGuide::coarse_path(const MeshPoint& a, const MeshPoint& b, int min_faces) {
  const int ca = nearest_kept(a), cb = nearest_kept(b);
  if (ca < 0 || cb < 0) return false;
  if (!solver_->shortest_path(vertex_point(coarse_, ca), vertex_point(coarse_, cb), path_, &stats_, SearchGraph::kDual))
    return false;
  if (static_cast<int>(path_.strip.size()) < min_faces) return false;
  path_positions(coarse_, path_, along_);
  return true;
}

void CoarseGuide::descend_to(const Vec3& x, const std::vector<Eigen::Vector3f>& centroids,
                             std::vector<int>& strip) const {
  const Eigen::Vector3f target = (x - fine_.centre).cast<float>();
  for (int f = strip.back();;) {
    int next = -1;
    float d = (centroids[f] - target).squaredNorm();
    for (int g : fine_.adjacency[f])
      if (g >= 0 && (centroids[g] - target).squaredNorm() < d) d = (centroids[g] - target).squaredNorm(), next = g;
    if (next < 0) return;
    strip.push_back(f = next);
  }
}

bool CoarseGuide::walk_to(const Vec3& x, Vec3& at, std::vector<int>& strip) const {
  // Barycentric weights of y's projection on face f's plane.
  auto weights_in = [&](int f, const Vec3& y) {
    const auto& t = fine_.triangles[f];
    const Vec3 &p0 = fine_.positions[t[0]], e1 = fine_.positions[t[1]] - p0, e2 = fine_.positions[t[2]] - p0;
    const Vec3 d = y - p0;
    const double a = e1.dot(e1), b = e1.dot(e2), c = e2.dot(e2), u = d.dot(e1), v = d.dot(e2), det = a * c - b * b;
    if (!(std::abs(det) > 0)) return Eigen::Vector3d(1.0 / 3, 1.0 / 3, 1.0 / 3);
    const double w1 = (c * u - b * v) / det, w2 = (a * v - b * u) / det;
    return Eigen::Vector3d(1 - w1 - w2, w1, w2);
  };
  int f = strip.back();
  for (size_t steps = 0; steps < kMaxWalk; ++steps) {
    const Eigen::Vector3d w0 = weights_in(f, at), w1 = weights_in(f, x);
    if (w1.minCoeff() >= -1e-12) {
      at = x;
      return true;
    }
    // Out across the edge opposite the corner whose weight turns negative first along the segment.
    int exit = -1;
    double first = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i)
      if (w1[i] < 0) {
        const double t = std::max(0.0, w0[i]) / (std::max(0.0, w0[i]) - w1[i]);
        if (t < first) first = t, exit = i;
      }
    const int g = fine_.adjacency[f][(exit + 1) % 3];
    if (g < 0 || (strip.size() > 1 && g == strip[strip.size() - 2])) return false;  // a boundary; turning back
    const Eigen::Vector3d w = w0 + first * (w1 - w0);
    const auto& t = fine_.triangles[f];
    at = w[0] * fine_.positions[t[0]] + w[1] * fine_.positions[t[1]] + w[2] * fine_.positions[t[2]];
    strip.push_back(f = g);
  }
  return false;
}

bool CoarseGuide::strip(const MeshPoint& a, const MeshPoint& b, int min_faces, DualSearch& search,
                        std::vector<int>& strip, PathStats* stats) {
  if (!coarse_path(a, b, min_faces)) return false;
  const std::vector<Eigen::Vector3f>& centroids = search.centroids();
  strip.assign(1, a.face);
  Vec3 at = eval_position(fine_, a);
  auto follow = [&](const Vec3& x) {
    if (!walks_ || !walk_to(x, at, strip)) descend_to(x, centroids, strip), at = x;
  };
  for (size_t k = 1; k + 1 < along_.size(); ++k) follow(along_[k]);
  follow(eval_position(fine_, b));
  if (strip.back() != b.face) {
    if (!search.initial_strip(MeshPoint{strip.back(), Vec2(1.0 / 3, 1.0 / 3)}, b, tail_, stats, SearchGraph::kDual))
      return false;
    strip.insert(strip.end(), tail_.begin() + 1, tail_.end());
  }
  remove_loops(strip, search.face_marks());
  return true;
}

double CoarseGuide::through_edge(int v, double dv, int u, double du, int w) const {
  // In the face's plane: v at the origin, u at (l, 0), w above the axis, the source below it.
  const Vec3 &pv = coarse_.positions[v], e = coarse_.positions[u] - pv, x = coarse_.positions[w] - pv;
  const double l = e.norm(), inf = std::numeric_limits<double>::infinity();
  if (!(l > 0)) return inf;
  const double xw = x.dot(e) / l, yw = std::sqrt(std::max(0.0, x.squaredNorm() - xw * xw));
  const double xs = (dv * dv - du * du + l * l) / (2 * l), ys2 = dv * dv - xs * xs;
  if (!(ys2 >= 0) || !(yw > 0)) return inf;
  const double ys = -std::sqrt(ys2);
  // (Only where the straight way from the source to w crosses the edge.)
  const double at = xs + (xw - xs) * (-ys) / (yw - ys);
  return at >= 0 && at <= l ? std::hypot(xw - xs, yw - ys) : inf;
}

bool CoarseGuide::corridor(const MeshPoint& a, const MeshPoint& b, double slack, double slack_edges,
                           std::vector<int>& face_marks, std::vector<int>& faces) {
  const int ca = nearest_kept(a), cb = nearest_kept(b);
  if (ca < 0 || cb < 0) return false;
  const double inf = std::numeric_limits<double>::infinity();
  if (from_a_.empty()) from_a_.assign(coarse_.positions.size(), inf), from_b_.assign(coarse_.positions.size(), inf);
  // Dijkstra over the coarse mesh from `source` into `dist` (the vertices reached into `touched`),
  // until the nearest open vertex lies farther than `limit` (or, with limit infinite, `stop` is
  // taken: then the limit is (1 + slack) times its distance and slack_edges mean edges more). With
  // `other`, the distances from the other end, vertices farther than `limit` from both ends together
  // are not expanded (every vertex within the limit of the first search is settled, so its distance
  // there is exact).
  auto dijkstra = [&](int source, std::vector<double>& dist, std::vector<int>& touched, double limit, int stop,
                      const std::vector<double>* other) {
    const auto later = [](const std::pair<double, int>& x, const std::pair<double, int>& y) {
      return x.first > y.first;
    };
    heap_.assign(1, {0.0, source});
    dist[source] = 0, touched.push_back(source);
    while (!heap_.empty()) {
      std::pop_heap(heap_.begin(), heap_.end(), later);
      const auto [d, v] = heap_.back();
      heap_.pop_back();
      if (d > dist[v]) continue;  // (stale)
      if (v == stop) limit = (1 + slack) * d + slack_edges * mean_edge_;
      if (d > limit) break;
      if (other && d + (*other)[v] > limit) continue;
      bool closed;
      vertex_fan(coarse_, v, fan_, closed);
      auto lower = [&](int w, double dw) {
        if (!(dw < dist[w])) return;
        if (std::isinf(dist[w])) touched.push_back(w);
        dist[w] = dw;
        heap_.emplace_back(dw, w), std::push_heap(heap_.begin(), heap_.end(), later);
      };
      for (int f : fan_) {
        const auto& t = coarse_.triangles[f];
        const int k = corner_of(coarse_, f, v);
        for (int side = 1; side <= 2; ++side) {
          const int w = t[(k + side) % 3], u = t[(k + 3 - side) % 3];
          lower(w, d + (coarse_.positions[w] - coarse_.positions[v]).norm());
          if (!std::isinf(dist[u])) lower(w, through_edge(v, d, u, dist[u], w));
        }
      }
    }
    return limit;
  };
  reached_.clear(), reached_b_.clear();
  const double bound = dijkstra(ca, from_a_, reached_, inf, cb, nullptr);
  const bool found = !std::isinf(from_a_[cb]);
  seeds_.clear();
  if (found) {
    dijkstra(cb, from_b_, reached_b_, bound, -1, &from_a_);
    // The coarse vertices on ways at most `bound` long, as the fine faces around their fine vertices.
    for (int v : reached_) {
      if (!(from_a_[v] + from_b_[v] <= bound)) continue;
      bool closed;
      vertex_fan(fine_, fine_of_coarse_[v], fan_, closed);
      seeds_.insert(seeds_.end(), fan_.begin(), fan_.end());
    }
    grow_faces(fine_, seeds_, mean_edge_, face_marks, faces);
  }
  for (int v : reached_) from_a_[v] = inf;
  for (int v : reached_b_) from_b_[v] = inf;
  return found;
}

}  // namespace splinekit::surface
