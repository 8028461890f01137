// Exact polyhedral geodesic distances from one source vertex to every vertex: a reference for tests
// and benchmarks (how far are our locally shortest paths from the true geodesic distance?).
//
// Algorithm: "continuous Dijkstra" window propagation of Mitchell, Mount & Papadimitriou,
//   J. S. B. Mitchell, D. M. Mount, C. H. Papadimitriou, "The discrete geodesic problem",
//   SIAM J. Comput. 16(4):647-668, 1987 (MMP),
// in the practical form of
//   V. Surazhsky, T. Surazhsky, D. Kirsanov, S. J. Gortler, H. Hoppe, "Fast exact and approximate
//   geodesics on meshes", ACM Trans. Graph. 24(3) (SIGGRAPH 2005),
// with the pseudo-source vertices of Chen & Han ("Shortest paths on a polyhedron", SCG 1990) as used
// by Xin & Wang ("Improving Chen and Han's algorithm on the discrete geodesic problem", ACM Trans.
// Graph. 28(4), 2009): a vertex through which shortest paths may bend (saddle vertex with total angle
// >= 2*pi, or boundary vertex) re-emits windows, with its own distance as offset, once its distance is
// final. Written from the papers for this project.
//
// How it works. A window is an interval [b0, b1] of an edge together with the unfolded position of
// a (pseudo-)source (sx, sy) in the edge's plane and that source's distance sigma: every point t of
// the interval is reached by the straight unfolded segment from the source, at distance
// sigma + |(t, 0) - (sx, sy)|. Windows are taken from a priority queue by their smallest distance and
// propagated across the face on the other side of their edge, which gives at most one child window
// on each of the two other edges. Each edge keeps its windows disjoint: a new window is compared with
// the ones already there (the distance functions of two windows cross where a quadratic vanishes)
// and every part of the edge is kept only by the window that is strictly shorter there, so the
// parts that survive are exactly the shortest-path field on the edge. Vertex distances are relaxed
// from every window (the straight ray to a vertex the window sees, or the path to a window end and on
// along the edge or across the face, which is always a real path, hence an upper bound that is exact
// once the window holding the true geodesic arrives). Everything is intrinsic: only edge lengths
// are used, faces are laid out in 2-D when they are crossed.
//
// Exactness and robustness. The result is exact up to floating-point rounding (about 1e-15
// relative on the meshes checked): no discretization of the distance field is involved. Near-ties are
// kept by the window already on the edge (relative 1e-13), slivers shorter than 1e-12 of the edge
// are dropped, and interior vertices whose total angle is at least 2*pi - 1e-6 (flat ones included,
// so that paths running exactly through a flat vertex survive rounding) are pseudo-sources; making
// more vertices pseudo-sources never changes the result, only the work.
//
// Complexity: O(n^2 log n) time and O(n^2) memory in the worst case (the MMP bound; n = #faces).
// In practice the number of windows grows like n^1.5 (each saddle vertex casts a thin shadow wedge
// that stays a window of its own as far as it reaches), about 50 bytes each. Measured, one source,
// g++ -O3, one core of the development machine (solve only; building the edge tables is < 0.3 s):
//   spot_control_tri.obj  (372 triangles)        ~1 ms        1.4 k windows
//   nefertiti.obj         (99,938 triangles)     1.4-1.5 s    2.1 M windows
//   spot_loop2_369k.ply   (368,992 triangles)    34 s         31 M windows, 1.75 GB peak
// Cross-checked on the meshes of ../shared/data against an independent MMP implementation (agreement
// to ~1e-15 relative; where they differed by 1e-8, an edge-flip shortest path confirmed this one).
//
// Input: positions #V x 3 doubles (row-major), triangles #F x 3 ints. The mesh must be manifold and
// consistently oriented (each directed edge in at most one triangle; boundaries and holes are fine);
// otherwise std::invalid_argument is thrown. Unreachable vertices get +infinity.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace splinekit::reference {

class ExactGeodesic {
 public:
  ExactGeodesic(const double* positions, int num_vertices, const int* triangles, int num_faces) {
    build(positions, num_vertices, triangles, num_faces);
  }

  // Distance from `source` to every vertex (+infinity where unreachable).
  std::vector<double> distances(int source) {
    if (source < 0 || source >= nv_) throw std::invalid_argument("exact_geodesic: source vertex out of range");
    reset();
    dist_[source] = 0;
    pseudo_source_queued(source);
    run();
    return dist_;
  }

  // Statistics of the last run (for benchmarks).
  std::size_t windows_created() const { return created_; }
  std::size_t windows_propagated() const { return propagated_; }

 private:
  struct Window {      // 48 bytes
    double b0, b1;     // interval, measured from the edge's lower-index vertex
    double sx, sy;     // unfolded (pseudo-)source in the edge frame (lower vertex at origin, x along the edge)
    double sigma;      // distance from the source to the pseudo-source
    int edge;          // undirected edge id
    signed char side;  // face the window propagates into: 0 = face on y > 0 of the edge frame, 1 = on y < 0
    bool alive, propagated;
  };
  // Monotone priority queue (radix heap over the bit patterns of non-negative doubles, which sort
  // like the numbers): keys never go below the last one taken, as in Dijkstra's algorithm, and every
  // operation is an append or a sweep over contiguous memory. A key that rounding puts a hair below
  // the last one taken is raised to it.
  class Queue {
   public:
    bool empty() const { return size_ == 0; }
    void clear() {
      for (auto& b : bucket_) b.clear();
      last_ = 0;
      size_ = 0;
    }
    void push(double key, int id) {
      std::uint64_t k = bits(key);
      if (k < last_) k = last_;
      bucket_[slot(k)].push_back({k, id});
      ++size_;
    }
    // Takes an entry with the smallest key; returns its id and key.
    int pop(double& key) {
      if (bucket_[0].empty()) {
        int i = 1;
        while (bucket_[i].empty()) ++i;
        std::uint64_t m = bucket_[i][0].key;
        for (const Item& it : bucket_[i]) m = std::min(m, it.key);
        last_ = m;
        for (const Item& it : bucket_[i]) bucket_[slot(it.key)].push_back(it);
        bucket_[i].clear();
      }
      const Item it = bucket_[0].back();
      bucket_[0].pop_back();
      --size_;
      std::memcpy(&key, &it.key, sizeof key);
      return it.id;
    }

   private:
    struct Item {
      std::uint64_t key;
      int id;
    };
    static std::uint64_t bits(double x) {
      std::uint64_t k;
      x = std::max(x, 0.0);
      std::memcpy(&k, &x, sizeof k);
      return k;
    }
    int slot(std::uint64_t k) const { return k == last_ ? 0 : 64 - __builtin_clzll(k ^ last_); }
    std::vector<Item> bucket_[65];
    std::uint64_t last_ = 0;
    std::size_t size_ = 0;
  };
  struct Span {
    double lo, hi;
  };

  static constexpr double kInf = std::numeric_limits<double>::infinity();
  static constexpr double kTieRel = 1e-13;     // near-ties go to the window already on the edge
  static constexpr double kSliverRel = 1e-12;  // pieces shorter than this fraction of the edge are dropped
  static constexpr double kFlatAngleTol = 1e-6;
  static constexpr double kTwoPi = 6.283185307179586476925;

  int nv_ = 0, nf_ = 0, ne_ = 0;
  std::vector<int> tri_;        // 3 per face
  std::vector<int> face_edge_;  // 3 per face: edge k joins tri[k] and tri[k+1]
  std::vector<int> edge_v_;     // 2 per edge: lower, higher vertex id
  std::vector<int> edge_f_;     // 2 per edge: face holding directed lower->higher (side 0), the other (side 1), or -1
  std::vector<double> len_;
  std::vector<int> vf_start_, vf_face_, vf_corner_;  // vertex -> incident (face, corner)
  std::vector<char> pseudo_;                         // saddle or boundary vertex

  std::vector<double> dist_, emitted_;
  std::vector<Window> win_;
  std::vector<int> free_;
  std::vector<std::vector<int>> edge_win_;
  Queue queue_;
  std::size_t created_ = 0, propagated_ = 0;
  std::vector<Span> n_remove_, e_remove_, pieces_;
  struct EdgeChange {
    int id;
    std::vector<Span> pieces;
  };
  std::vector<EdgeChange> changes_;

  void build(const double* P, int nv, const int* T, int nf) {
    if (nv < 0 || nf < 0 || (nf > 0 && (!P || !T))) throw std::invalid_argument("exact_geodesic: bad mesh arrays");
    nv_ = nv;
    nf_ = nf;
    tri_.assign(T, T + 3 * std::size_t(nf));
    face_edge_.assign(3 * std::size_t(nf), -1);
    std::unordered_map<std::uint64_t, int> edge_of;
    edge_of.reserve(std::size_t(nf) * 2);
    for (int f = 0; f < nf; ++f) {
      for (int k = 0; k < 3; ++k) {
        const int u = tri_[3 * f + k], v = tri_[3 * f + (k + 1) % 3];
        if (u < 0 || u >= nv || v < 0 || v >= nv)
          throw std::invalid_argument("exact_geodesic: triangle index out of range");
        if (u == v) throw std::invalid_argument("exact_geodesic: degenerate triangle " + std::to_string(f));
        const int a = std::min(u, v), b = std::max(u, v);
        const std::uint64_t key = (std::uint64_t(a) << 32) | std::uint32_t(b);
        auto [it, fresh] = edge_of.emplace(key, ne_);
        if (fresh) {
          ++ne_;
          edge_v_.push_back(a);
          edge_v_.push_back(b);
          edge_f_.push_back(-1);
          edge_f_.push_back(-1);
          const double dx = P[3 * b] - P[3 * a], dy = P[3 * b + 1] - P[3 * a + 1], dz = P[3 * b + 2] - P[3 * a + 2];
          len_.push_back(std::sqrt(dx * dx + dy * dy + dz * dz));
        }
        const int e = it->second, side = u < v ? 0 : 1;
        if (edge_f_[2 * e + side] != -1)
          throw std::invalid_argument("exact_geodesic: mesh is not manifold or not consistently oriented (edge " +
                                      std::to_string(a) + "-" + std::to_string(b) + ")");
        edge_f_[2 * e + side] = f;
        face_edge_[3 * f + k] = e;
      }
    }
    // Vertex -> faces, corner angles, pseudo-sources.
    vf_start_.assign(nv + 1, 0);
    for (int i = 0; i < 3 * nf; ++i) ++vf_start_[tri_[i] + 1];
    for (int v = 0; v < nv; ++v) vf_start_[v + 1] += vf_start_[v];
    vf_face_.resize(3 * std::size_t(nf));
    vf_corner_.resize(3 * std::size_t(nf));
    std::vector<int> fill(vf_start_.begin(), vf_start_.end() - 1);
    std::vector<double> angle(nv, 0.0);
    for (int f = 0; f < nf; ++f) {
      for (int k = 0; k < 3; ++k) {
        const int v = tri_[3 * f + k];
        vf_face_[fill[v]] = f;
        vf_corner_[fill[v]++] = k;
        const double a = len_[face_edge_[3 * f + k]], b = len_[face_edge_[3 * f + (k + 2) % 3]],
                     c = len_[face_edge_[3 * f + (k + 1) % 3]];
        const double denom = 2 * a * b;
        const double cosv = denom > 0 ? (a * a + b * b - c * c) / denom : 1.0;
        angle[v] += std::acos(std::clamp(cosv, -1.0, 1.0));
      }
    }
    pseudo_.assign(nv, 0);
    for (int v = 0; v < nv; ++v) pseudo_[v] = angle[v] >= kTwoPi - kFlatAngleTol;
    for (int e = 0; e < ne_; ++e)
      if (edge_f_[2 * e] < 0 || edge_f_[2 * e + 1] < 0) pseudo_[edge_v_[2 * e]] = pseudo_[edge_v_[2 * e + 1]] = 1;
    edge_win_.assign(ne_, {});
  }

  void reset() {
    dist_.assign(nv_, kInf);
    emitted_.assign(nv_, kInf);
    win_.clear();
    free_.clear();
    for (auto& l : edge_win_) l.clear();
    queue_.clear();
    created_ = propagated_ = 0;
  }

  // Third vertex c of face f seen from edge e, laid out in the frame of e with y >= 0 (magnitude only).
  struct Layout {
    int c;
    double x, y;
    int edge_ac, edge_bc;  // a, b = lower, higher vertex of e
  };
  Layout layout(int f, int e) const {
    int j = 0;
    while (face_edge_[3 * f + j] != e) ++j;
    const int c = tri_[3 * f + (j + 2) % 3];
    const int e1 = face_edge_[3 * f + (j + 1) % 3];  // tri[j+1] - c
    const int e2 = face_edge_[3 * f + (j + 2) % 3];  // c - tri[j]
    Layout out;
    out.c = c;
    if (tri_[3 * f + j] == edge_v_[2 * e]) {
      out.edge_ac = e2;
      out.edge_bc = e1;
    } else {
      out.edge_ac = e1;
      out.edge_bc = e2;
    }
    const double L = len_[e], lac = len_[out.edge_ac], lbc = len_[out.edge_bc];
    out.x = (lac * lac - lbc * lbc + L * L) / (2 * L);
    out.y = std::sqrt(std::max(lac * lac - out.x * out.x, 0.0));
    out.y = std::max(out.y, 1e-12 * L);  // zero-area faces: a hair of height keeps the frames well defined
    return out;
  }

  void relax(int v, double d) {
    if (d < dist_[v]) {
      dist_[v] = d;
      if (pseudo_[v]) pseudo_source_queued(v);
    }
  }
  void pseudo_source_queued(int v) { queue_.push(dist_[v], -(v + 1)); }  // ids < 0: pseudo-source vertices

  static double norm2(double x, double y) { return std::sqrt(x * x + y * y); }
  static double distance_at(const Window& w, double t) { return w.sigma + norm2(t - w.sx, w.sy); }
  static double window_key(const Window& w) { return distance_at(w, std::clamp(w.sx, w.b0, w.b1)); }

  // Points of (lo, hi) where the distance functions of n and e may cross: roots of the squared equation
  // plus its near-double-root, all harmless extra splits (each piece is classified at its midpoint).
  static int crossing_candidates(const Window& n, const Window& e, double lo, double hi, double* out) {
    const double xN = n.sx - lo, yN = n.sy, xE = e.sx - lo, yE = e.sy, c = e.sigma - n.sigma;
    // sqrt((t-xN)^2+yN^2) - sqrt((t-xE)^2+yE^2) = c  ->  alpha t + g = 2 c sqrt(B)  ->  qa t^2 + qb t + qc = 0
    const double alpha = 2 * (xE - xN);
    const double g = (xN * xN + yN * yN) - (xE * xE + yE * yE) - c * c;
    const double qa = alpha * alpha - 4 * c * c;
    const double qb = 2 * alpha * g + 8 * c * c * xE;
    const double qc = g * g - 4 * c * c * (xE * xE + yE * yE);
    double r[4];
    int m = 0;
    if (alpha != 0) r[m++] = -g / alpha;  // the c = 0 root, and close to both roots when c is small
    if (qa != 0) {
      r[m++] = -qb / (2 * qa);
      const double disc = qb * qb - 4 * qa * qc;
      if (disc > 0) {
        const double s = std::sqrt(disc);
        const double q = -0.5 * (qb + (qb >= 0 ? s : -s));
        if (q != 0) {
          r[m++] = q / qa;
          r[m++] = qc / q;
        }
      }
    } else if (qb != 0) {
      r[m++] = -qc / qb;
    }
    const double w = hi - lo;
    int k = 0;
    for (int i = 0; i < m; ++i)
      if (r[i] > 0 && r[i] < w && std::isfinite(r[i])) out[k++] = r[i] + lo;
    for (int i = 1; i < k; ++i)  // insertion sort of at most 4 values
      for (int j = i; j > 0 && out[j] < out[j - 1]; --j) std::swap(out[j], out[j - 1]);
    return k;
  }

  // [a, b] minus the union of `remove`, keeping pieces longer than min_len.
  static void subtract(double a, double b, std::vector<Span>& remove, double min_len, std::vector<Span>& out) {
    out.clear();
    std::sort(remove.begin(), remove.end(), [](const Span& x, const Span& y) { return x.lo < y.lo; });
    double cur = a;
    for (const Span& r : remove) {
      if (r.lo > cur && r.lo - cur > min_len) out.push_back({cur, std::min(r.lo, b)});
      cur = std::max(cur, r.hi);
      if (cur >= b) break;
    }
    if (b - cur > min_len) out.push_back({cur, b});
  }

  // The filter of Xin & Wang (2009) on the ends of the edge: where the path through an end vertex
  // (its current distance, a real path, plus the run along the edge) is strictly shorter, the window is
  // of no use. Along the edge that excess is monotone, so the useless part is one end of [a, b] and is
  // cut off in closed form. Returns false when nothing is left.
  bool vertex_filter(int e, double& a, double& b, double sx, double sy, double sigma) const {
    const double L = len_[e];
    // Lower vertex at t = 0: excess(t) = sigma + |(t,0) - s| - d - t, nonincreasing in t.
    // Upper vertex at t = L: the same in the mirrored coordinate L - t.
    for (int end = 0; end < 2; ++end) {
      const double d = dist_[edge_v_[2 * e + end]];
      if (!(d < kInf)) continue;
      const double tol = kTieRel * (d + L);
      const double x = end == 0 ? sx : L - sx;
      double lo = end == 0 ? a : L - b, hi = end == 0 ? b : L - a;  // interval in the mirrored coordinate
      auto excess = [&](double t) { return sigma + norm2(t - x, sy) - d - t; };
      if (excess(hi) > tol) return false;
      if (!(excess(lo) > tol)) continue;
      // sqrt((t-x)^2 + y^2) = t + c with c = d + tol - sigma  ->  t = (x^2 + y^2 - c^2) / (2 (x + c))
      const double c = d + tol - sigma;
      const double t = (x * x + sy * sy - c * c) / (2 * (x + c));
      if (!(t > lo && t < hi)) continue;  // rounding: keep everything
      lo = t;
      if (end == 0)
        a = lo;
      else
        b = L - lo;
    }
    return b > a;
  }

  int new_window(const Window& w) {
    int id;
    if (!free_.empty()) {
      id = free_.back();
      free_.pop_back();
      win_[id] = w;
    } else {
      id = int(win_.size());
      win_.push_back(w);
    }
    win_[id].alive = true;
    ++created_;
    return id;
  }

  // Adds the window (edge e, propagating into `side`) with interval [a, b], keeping only the parts
  // where it is strictly shorter than the windows already on the edge and trimming those where it is.
  void insert(int e, int side, double a, double b, double sx, double sy, double sigma) {
    const double L = len_[e];
    a = std::max(a, 0.0);
    b = std::min(b, L);
    if (b < a) return;
    // Real paths: straight to the window end, then along the edge to its vertex.
    relax(edge_v_[2 * e], sigma + norm2(a - sx, sy) + a);
    relax(edge_v_[2 * e + 1], sigma + norm2(b - sx, sy) + (L - b));
    if (edge_f_[2 * e + side] < 0) return;  // boundary edge: nothing to propagate into
    const double min_len = kSliverRel * L;
    if (!vertex_filter(e, a, b, sx, sy, sigma) || b - a <= min_len) return;
    const Window n{a, b, sx, sy, sigma, e, static_cast<signed char>(side), true, false};
    n_remove_.clear();
    changes_.clear();
    auto& list = edge_win_[e];
    for (int id : list) {
      const Window& w = win_[id];
      const double lo = std::max(a, w.b0), hi = std::min(b, w.b1);
      if (hi - lo <= min_len) continue;
      double pts[6];
      pts[0] = lo;
      const int k = crossing_candidates(n, w, lo, hi, pts + 1);
      pts[k + 1] = hi;
      e_remove_.clear();
      for (int i = 0; i <= k; ++i) {
        const double p = pts[i], q = pts[i + 1];
        if (q <= p) continue;
        const double m = 0.5 * (p + q), dn = distance_at(n, m), dw = distance_at(w, m);
        if (dn < dw - kTieRel * dw)
          e_remove_.push_back({p, q});
        else
          n_remove_.push_back({p, q});
      }
      if (!e_remove_.empty()) {
        changes_.push_back({id, {}});
        subtract(w.b0, w.b1, e_remove_, min_len, changes_.back().pieces);
      }
    }
    for (EdgeChange& ch : changes_) {
      Window& w = win_[ch.id];
      if (ch.pieces.empty()) {
        w.alive = false;
        list.erase(std::find(list.begin(), list.end(), ch.id));
        free_.push_back(ch.id);
        continue;
      }
      const double old_key = window_key(w);
      w.b0 = ch.pieces[0].lo;
      w.b1 = ch.pieces[0].hi;
      if (!w.propagated && window_key(w) != old_key) queue_.push(window_key(w), ch.id);
      for (std::size_t i = 1; i < ch.pieces.size(); ++i) {
        Window copy = win_[ch.id];
        copy.b0 = ch.pieces[i].lo;
        copy.b1 = ch.pieces[i].hi;
        const int id = new_window(copy);
        list.push_back(id);
        if (!win_[id].propagated) queue_.push(window_key(win_[id]), id);
      }
    }
    subtract(a, b, n_remove_, min_len, pieces_);
    for (const Span& s : pieces_) {
      Window piece = n;
      piece.b0 = s.lo;
      piece.b1 = s.hi;
      const int id = new_window(piece);
      list.push_back(id);
      queue_.push(window_key(win_[id]), id);
    }
  }

  // Child window on edge e2 of face f, whose endpoints p (lower id) and q sit at pp, pq in the working
  // frame; wpos is the vertex of f opposite e2; the child interval is between points q0 and q1.
  void child(int f, int e2, const double* pp, const double* pq, const double* wpos, const double* q0, const double* q1,
             double sx, double sy, double sigma) {
    const int s2 = edge_f_[2 * e2] == f ? 0 : 1;
    double ux = pq[0] - pp[0], uy = pq[1] - pp[1];
    const double l = norm2(ux, uy);
    ux /= l;
    uy /= l;
    const double ix = sx - pp[0], iy = sy - pp[1];
    const double x = ux * ix + uy * iy, yr = ux * iy - uy * ix;
    const double yw = ux * (wpos[1] - pp[1]) - uy * (wpos[0] - pp[0]);
    const double y = ((yw > 0) == (s2 == 0)) ? yr : -yr;
    double t0 = ux * (q0[0] - pp[0]) + uy * (q0[1] - pp[1]);
    double t1 = ux * (q1[0] - pp[0]) + uy * (q1[1] - pp[1]);
    if (t0 > t1) std::swap(t0, t1);
    insert(e2, 1 - s2, t0, t1, x, y, sigma);
  }

  void propagate(const Window& w) {
    const int e = w.edge, f = edge_f_[2 * e + w.side];
    if (f < 0) return;
    const double L = len_[e];
    const Layout lay = layout(f, e);
    const double x3 = lay.x, y3 = lay.y;
    // Working frame: face f on y > 0, the source below the edge.
    const double sx = w.sx, sy = w.side == 0 ? w.sy : -w.sy;
    if (!(sy < 0)) return;  // source on the edge line: its rays run along the edge, never into f
    const double sigma = w.sigma;
    const double xv = sx - sy * (x3 - sx) / (y3 - sy);  // where the ray to the third vertex crosses the edge
    const double pa[2] = {0, 0}, pb[2] = {L, 0}, pc[2] = {x3, y3};
    const int va = edge_v_[2 * e], vb = edge_v_[2 * e + 1], vc = lay.c;
    if (w.b0 <= xv && xv <= w.b1) relax(vc, sigma + norm2(x3 - sx, y3 - sy));  // the window sees the vertex
    // Rays left of the third vertex cross edge a-c; the image of (t, 0) is the point s*(x3, y3) of a-c.
    if (w.b0 < xv) {
      const double c0 = w.b0, c1 = std::min(w.b1, xv);
      auto image = [&](double t) { return std::clamp(t * sy / ((t - sx) * y3 + sy * x3), 0.0, 1.0); };
      const double s0 = image(c0), s1 = c1 >= xv ? 1.0 : image(c1);
      const double q0[2] = {s0 * x3, s0 * y3}, q1[2] = {s1 * x3, s1 * y3};
      const int e2 = lay.edge_ac;
      const bool a_low = edge_v_[2 * e2] == va;
      child(f, e2, a_low ? pa : pc, a_low ? pc : pa, pb, q0, q1, sx, sy, sigma);
    }
    // Rays right of it cross edge b-c; the image of (t, 0) is b + s*(c - b).
    if (w.b1 > xv) {
      const double c0 = std::max(w.b0, xv), c1 = w.b1;
      auto image = [&](double t) { return std::clamp((t - L) * sy / ((t - sx) * y3 + sy * (x3 - L)), 0.0, 1.0); };
      const double s0 = c0 <= xv ? 1.0 : image(c0), s1 = image(c1);
      const double q0[2] = {L + s0 * (x3 - L), s0 * y3}, q1[2] = {L + s1 * (x3 - L), s1 * y3};
      const int e2 = lay.edge_bc;
      const bool b_low = edge_v_[2 * e2] == vb;
      child(f, e2, b_low ? pb : pc, b_low ? pc : pb, pa, q0, q1, sx, sy, sigma);
    }
    (void)vc;
  }

  // A pseudo-source vertex sends a full window over the opposite edge of each face around it.
  void emit(int v) {
    for (int i = vf_start_[v]; i < vf_start_[v + 1]; ++i) {
      const int f = vf_face_[i], k = vf_corner_[i];
      const int e = face_edge_[3 * f + (k + 1) % 3];
      const Layout lay = layout(f, e);
      const int side_f = edge_f_[2 * e] == f ? 0 : 1;
      insert(e, 1 - side_f, 0, len_[e], lay.x, side_f == 0 ? lay.y : -lay.y, dist_[v]);
    }
  }

  void run() {
    while (!queue_.empty()) {
      double top_key;
      const int top_id = queue_.pop(top_key);
      if (top_id < 0) {
        // The entry of the vertex's current distance comes first; later (older) ones find it emitted.
        const int v = -top_id - 1;
        if (emitted_[v] < kInf && dist_[v] >= emitted_[v] - 1e-12 * emitted_[v]) continue;
        emitted_[v] = dist_[v];
        emit(v);
        continue;
      }
      Window& w = win_[top_id];
      // Stale entries: the window died, was propagated, or was trimmed to a larger key (and queued
      // again). A reused slot whose new window is due by now is simply propagated now.
      if (!w.alive || w.propagated || window_key(w) > top_key) continue;
      // Vertex distances may have dropped since the window was queued: filter it again.
      double a = w.b0, b = w.b1;
      if (!vertex_filter(w.edge, a, b, w.sx, w.sy, w.sigma)) {
        w.alive = false;
        auto& list = edge_win_[w.edge];
        list.erase(std::find(list.begin(), list.end(), top_id));
        free_.push_back(top_id);
        continue;
      }
      if (a != w.b0 || b != w.b1) {
        w.b0 = a;
        w.b1 = b;
        const double key = window_key(w);
        if (key > top_key) {  // its turn comes later
          queue_.push(key, top_id);
          continue;
        }
      }
      w.propagated = true;
      ++propagated_;
      const Window copy = w;  // insert() may grow win_
      propagate(copy);
    }
  }
};

// Exact geodesic distance from vertex `source` to every vertex of a triangle mesh.
// positions: #V x 3 doubles (row-major), triangles: #F x 3 ints; the mesh must be manifold and
// consistently oriented (it may have boundaries). Returns +infinity for unreachable vertices.
// Throws std::invalid_argument on a bad mesh or source.
inline std::vector<double> exact_geodesic_distances(const double* positions, int num_vertices, const int* triangles,
                                                    int num_faces, int source) {
  ExactGeodesic solver(positions, num_vertices, triangles, num_faces);
  return solver.distances(source);
}

}  // namespace splinekit::reference
