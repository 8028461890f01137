#include "surface/straighten.h"

#include <algorithm>
#include <limits>

namespace splinekit::surface {

double corner_angle(const TriMesh& mesh, int face, int v) {
  const auto& t = mesh.triangles[face];
  const int k = corner_of(mesh, face, v);
  const Vec3 a = mesh.positions[t[(k + 1) % 3]] - mesh.positions[v],
             b = mesh.positions[t[(k + 2) % 3]] - mesh.positions[v];
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

Straightener::Straightener(const TriMesh& mesh, std::vector<int>& face_marks, const ShortestPathOptions& options)
    : options(options), mesh_(mesh), face_marks_(face_marks) {
  angle_sums_.assign(mesh.positions.size(), std::numeric_limits<double>::quiet_NaN());
}

// =================================================================================================
// The whole straightening
// =================================================================================================

bool Straightener::straighten(const MeshPoint& a, const MeshPoint& b, std::vector<int>& strip, GeodesicPath& path,
                              PathStats* stats, int max_passes) {
  path.strip = strip;
  point_in_face(mesh_, a, strip.front(), path.start);
  point_in_face(mesh_, b, strip.back(), path.end);
  path.lerps.clear();
  path.arc.clear();
  if (stats) stats->strip_faces += static_cast<int>(strip.size());
  if (strip.size() == 1) return true;
  begin(path.start, path.end, strip);
  const int limit = max_passes < 0 ? options.max_passes : max_passes;
  bool shortest = !options.straighten;
  for (int passes = 0; options.straighten && passes < limit; ++passes) {
    if (stats) ++stats->passes;
    if (!pass(stats)) {
      shortest = true;
      break;
    }
  }
  // Crossings of the final strip.
  crossings(path_.unfolded, path_.apices, path.lerps, path.arc);
  strip.assign(path_.strip.begin(), path_.strip.end());
  path.strip = path_.strip;
  return shortest;
}

void Straightener::begin(const MeshPoint& start, const MeshPoint& end, const std::vector<int>& strip) {
  frozen_.clear(), frozen_cos_.clear(), no_chain_.clear(), no_chord_.clear(), failed_chords_.clear();
  windows_off_ = false;
  span_failures_ = 0;
  // The strip laid out last for these end points, no pass since (a candidate measured before it was
  // chosen, GeodesicSolver::shortest_path): its layout and funnel path stand.
  auto same = [](const MeshPoint& x, const MeshPoint& y) { return x.face == y.face && x.uv == y.uv; };
  if (laid_ && same(start, path_.start) && same(end, path_.end) && strip == path_.strip) return;
  path_.start = start, path_.end = end;
  path_.strip.assign(strip.begin(), strip.end());
  unfold_strip(mesh_, path_.strip, path_.unfolded);
  path_.length = shorten(path_.unfolded, path_.made, path_.apices, nullptr);
  laid_ = true;
}

double Straightener::shorten(const UnfoldedStrip& u, std::vector<Apex>& raw, std::vector<Apex>& out,
                             const Splice* splice) const {
  funnel(u, u.map(0, path_.start), u.map(static_cast<int>(u.faces.size()) - 1, path_.end), raw, splice);
  out.assign(raw.begin(), raw.end());
  drop_straight(out);
  return polyline_length(out);
}

// =================================================================================================
// Queries
// =================================================================================================

bool Straightener::run_of(int v, int at, int& first, int& last) const {
  const int n = static_cast<int>(path_.strip.size());
  first = last = std::clamp(at, 0, n - 1);
  if (!contains_vertex(mesh_, path_.strip[first], v)) return false;
  while (first > 0 && contains_vertex(mesh_, path_.strip[first - 1], v)) --first;
  while (last + 1 < n && contains_vertex(mesh_, path_.strip[last + 1], v)) ++last;
  return true;
}

bool Straightener::on_left(const Apex& x) const {
  return path_.unfolded.portals[std::clamp(x.portal, 0, static_cast<int>(path_.unfolded.portals.size()) - 1)]
             .left_vertex == x.vertex;
}

bool Straightener::overlaps(int first, int last) const {
  const int n = static_cast<int>(path_.strip.size());
  for (int i = std::max(0, first - 1), end = std::min(n - 1, last + 1); i <= end; ++i)
    if (taken_[i]) return true;
  return false;
}

bool Straightener::is_frozen(int v, double turn) const {
  const double* up_to = frozen_.find(v);
  return up_to && turn <= *up_to + 1e-9;
}

void Straightener::freeze(int v, double turn, PathStats* stats) {
  // Where v's angle sum is known, the path is locally shortest there for every turn up to θ − 2π.
  if (!std::isnan(angle_sums_[v]) && straight_through(v, turn)) turn = std::max(turn, angle_sums_[v] - 2 * kPi);
  frozen_.insert(v, turn);
  const double up_to = turn + 1e-9;  // (as is_frozen compares)
  frozen_cos_.insert(v, up_to >= kPi ? -2 : std::cos(up_to));
  if (stats) ++stats->frozen_vertices;
}

bool Straightener::surely_frozen(size_t j) const {
  const double* bound = frozen_cos_.find(path_.apices[j].vertex);
  if (!bound) return false;
  // cos(turn) = a·b / (|a||b|) against the bound, with a margin (1e-12) far above the rounding of
  // both and of atan2: where it holds, the turn turn_at computes is below the frozen one too.
  const Vec2 a = path_.apices[j].pos - path_.apices[j - 1].pos, b = path_.apices[j + 1].pos - path_.apices[j].pos;
  const double norms = a.norm() * b.norm();
  return norms > 0 && a.dot(b) >= (*bound + 1e-12) * norms;
}

void VertexSet::insert(int v, double value) {
  if (2 * (keys_.size() + 1) > slots_.size()) {  // grow: twice the slots, the keys again
    std::vector<int> old_slots(std::max<size_t>(64, 2 * slots_.size()), -1);
    std::vector<double> old_values(old_slots.size());
    old_slots.swap(slots_), old_values.swap(values_);
    for (size_t k = 0; k < old_slots.size(); ++k) {
      if (old_slots[k] < 0) continue;
      size_t i = slot(old_slots[k]);
      while (slots_[i] >= 0) i = (i + 1) & (slots_.size() - 1);
      slots_[i] = old_slots[k], values_[i] = old_values[k];
    }
  }
  size_t i = slot(v);
  for (; slots_[i] >= 0; i = (i + 1) & (slots_.size() - 1))
    if (slots_[i] == v) {
      values_[i] = value;
      return;
    }
  slots_[i] = v, values_[i] = value;
  keys_.push_back(v);
}

void VertexSet::clear() {
  // Each key's slot, freed: its probe ends on it (it is still in), whatever it passes on the way.
  for (int k : keys_) {
    size_t i = slot(k);
    while (slots_[i] != k) i = (i + 1) & (slots_.size() - 1);
    slots_[i] = -1;
  }
  keys_.clear();
}

// =================================================================================================
// The pass
// =================================================================================================

bool Straightener::pass(PathStats* stats) {
  laid_ = false;
  const int n = static_cast<int>(path_.strip.size());
  if (stats) stats->pass_faces += n;
  // Every removable reflex vertex, largest turn first, with runs that do not touch each other.
  order_.clear();
  for (size_t j = 1; j + 1 < path_.apices.size(); ++j) {
    if (path_.apices[j].vertex < 0 || surely_frozen(j)) continue;
    const double turn = turn_at(path_.apices, j);
    if (turn > 1e-9 && !is_frozen(path_.apices[j].vertex, turn)) order_.emplace_back(-turn, j);
  }
  if (order_.empty()) return false;
  // The same apices in path order, for windows and spans.
  candidates_.clear();
  for (const auto& entry : order_) candidates_.push_back(entry.second);
  std::sort(candidates_.begin(), candidates_.end());
  if (taken_.size() < static_cast<size_t>(n)) taken_.resize(n, 0);
  if (!in_window_ && windowed_pass(stats)) return true;
  if (span_pass(stats)) return true;
  std::sort(order_.begin(), order_.end());
  used_ = 0;
  for (const auto& [neg_turn, j] : order_) {
    // A vertex whose faces a flip of this pass already changes cannot flip in it; it is only
    // frozen (as `flip` would) if the path through it is locally shortest.
    int run_first, run_last;
    const int v = path_.apices[j].vertex;
    const bool in_strip = run_of(v, path_.apices[j].portal, run_first, run_last);
    const bool blocked = in_strip && used_ > 0 && overlaps(run_first, run_last);
    if (blocked && !std::isnan(angle_sums_[v])) {
      if (straight_through(v, -neg_turn)) freeze(v, -neg_turn, stats);
      continue;
    }
    if (used_ == flips_.size()) flips_.emplace_back();
    Flip& made = flips_[used_];
    if (!in_strip || !flip(j, -neg_turn, run_first, run_last, made)) {
      // Locally shortest at this turn, or (not in the strip, a boundary vertex) not to be flipped.
      const bool straight = in_strip && !std::isnan(angle_sums_[v]) && straight_through(v, -neg_turn);
      freeze(v, straight ? -neg_turn : std::numeric_limits<double>::infinity(), stats);
      continue;
    }
    if (blocked) continue;
    // A chord spans the faces around the neighbouring apices: look for room before tracing it.
    ChordRoom room{0, n - 1, n - 1};
    int unused;
    const bool fits = options.chords && -neg_turn > options.chord_min_turn &&
                      (path_.apices[j - 1].vertex < 0 ||
                       run_of(path_.apices[j - 1].vertex, path_.apices[j - 1].portal, room.p_first, unused)) &&
                      (path_.apices[j + 1].vertex < 0 ||
                       run_of(path_.apices[j + 1].vertex, path_.apices[j + 1].portal, room.q_first, room.q_last)) &&
                      !overlaps(room.p_first, room.q_last);
    const bool try_chord = fits && !no_chord_.contains(made.vertex);
    if (try_chord && stats) ++stats->chords_tried;
    bool slid = false;
    if (options.slides && !no_chain_.contains(made.vertex)) {
      size_t ahead;
      const size_t back = slide(j, ahead);
      if (back > 1 || ahead > 1) zipper(j, made, back, ahead), slid = made.chain;
    }
    if (!slid && (!try_chord || !walk_chord(j, room, made))) {
      int lo, hi;
      if (options.glides && !no_chain_.contains(made.vertex) && glide(j, lo, hi)) zipper(j, made, 1, 1, lo, hi);
      if (!made.chain) zipper(j, made);
    }
    if (!overlaps(made.first, made.last)) take(made);
  }
  end_taking(stats);
  if (used_ == 0) return true;  // all frozen this pass; the next pass finds nothing new
  chosen_.clear();
  for (size_t i = 0; i < used_; ++i) chosen_.push_back(&flips_[i]);
  std::sort(chosen_.begin(), chosen_.end(), [](const Flip* x, const Flip* y) { return x->first < y->first; });
  double trial_length = lay_trial(chosen_);
  if (!(trial_length < path_.length - 1e-12 * mesh_.scale) && chosen_.size() > 1) {
    // Together they did not shorten the path: fall back to the largest turn alone. The others'
    // zippers and chords are not tried again (a semi-star at a reflex vertex shortens the path,
    // a zipper or chord need not; one that does not kept the group failing pass after pass).
    const Flip* best = *std::max_element(chosen_.begin(), chosen_.end(),
                                         [](const Flip* x, const Flip* y) { return x->turn < y->turn; });
    for (const Flip* f : chosen_) {
      if (f == best) continue;
      if (f->chord) no_chord_.insert(f->vertex);
      if (f->chain) no_chain_.insert(f->vertex);
    }
    chosen_.assign(1, best);
    trial_length = lay_trial(chosen_);
  }
  if (keep_trial(trial_length)) {
    if (stats) {
      stats->accepted_flips += static_cast<int>(chosen_.size());
      for (const Flip* f : chosen_) stats->chords_kept += f->chord;
    }
  } else {
    for (const Flip* f : chosen_) {
      if (f->chord) {
        no_chord_.insert(f->vertex);
      } else if (f->chain) {
        no_chain_.insert(f->vertex);
      } else {
        freeze(f->vertex, f->turn, stats);
      }
    }
  }
  return true;
}

void Straightener::take(const Flip& made) {
  std::fill(taken_.begin() + made.first, taken_.begin() + made.last + 1, 1);
  ++used_;
}

void Straightener::end_taking(PathStats* stats) {
  for (size_t i = 0; i < used_; ++i)
    std::fill(taken_.begin() + flips_[i].first, taken_.begin() + flips_[i].last + 1, 0);
  if (stats) stats->walked_faces += walked_;
  walked_ = 0;
}

bool Straightener::span_pass(PathStats* stats) {
  if (!options.chords || options.span_min_bends <= 0 || span_failures_ >= options.span_failures) return false;
  const int n = static_cast<int>(path_.strip.size());
  // Runs of consecutive reflex apices (candidates_) whose vertices cannot hold a bend of the path.
  auto spannable = [&](size_t k) { return holds_no_bend(path_.apices[candidates_[k]].vertex); };
  used_ = 0;
  for (size_t r = 0; r < candidates_.size();) {
    if (!spannable(r)) {
      ++r;
      continue;
    }
    size_t e = r + 1;  // the run candidates_[r .. e-1]
    while (e < candidates_.size() && candidates_[e] == candidates_[e - 1] + 1 && spannable(e)) ++e;
    const size_t jp = candidates_[r] - 1, jq = candidates_[e - 1] + 1;
    r = e;
    if (jq - jp - 1 < static_cast<size_t>(options.span_min_bends)) continue;
    ChordRoom room{0, n - 1, n - 1};
    int unused;
    const Apex &p = path_.apices[jp], &q = path_.apices[jq];
    if (p.vertex >= 0 && !run_of(p.vertex, p.portal, room.p_first, unused)) continue;
    if (q.vertex >= 0 && !run_of(q.vertex, q.portal, room.q_first, room.q_last)) continue;
    if (overlaps(room.p_first, room.q_last)) continue;
    if (used_ == flips_.size()) flips_.emplace_back();
    Flip& made = flips_[used_];
    made.vertex = -1, made.turn = 0, made.chain = false;
    if (stats) ++stats->chords_tried;
    if (chord(jp, jq, room, made, options.span_aims)) take(made);
  }
  end_taking(stats);
  if (used_ > 0) {
    chosen_.clear();
    for (size_t i = 0; i < used_; ++i) chosen_.push_back(&flips_[i]);
    if (keep_trial(lay_trial(chosen_))) {
      if (stats) stats->accepted_flips += static_cast<int>(used_), stats->chords_kept += static_cast<int>(used_);
      return true;
    }
  }
  ++span_failures_;
  return false;
}

double Straightener::lay_trial(const std::vector<const Flip*>& chosen) {
  apply(chosen, trial_.strip, trial_.unfolded, splice_);
  return shorten(trial_.unfolded, trial_.made, trial_.apices, splice_.path ? &splice_ : nullptr);
}

bool Straightener::keep_trial(double trial_length) {
  if (!(trial_length < path_.length - 1e-12 * mesh_.scale)) return false;
  trial_.start = path_.start, trial_.end = path_.end, trial_.length = trial_length;
  std::swap(path_, trial_);
  return true;
}

// =================================================================================================
// Windows
// =================================================================================================

bool Straightener::windowed_pass(PathStats* stats) {
  const int n = static_cast<int>(path_.strip.size());
  if (windows_off_) {  // (the last windowed pass changed nothing: this one is whole)
    windows_off_ = false;
    return false;
  }
  if (options.window_min_faces <= 0 || n < options.window_min_faces) return false;
  const size_t end = path_.apices.size() - 1;
  auto candidate = [&](size_t j) { return std::binary_search(candidates_.begin(), candidates_.end(), j); };
  // A window from apex ja to apex jb holds the faces from the last around ja to the first around jb.
  auto first_after = [&](size_t ja) { return ja == 0 ? 0 : path_.apices[ja].portal + 1; };
  auto last_before = [&](size_t jb) {
    if (jb == end) return n - 1;
    const int v = path_.apices[jb].vertex;
    int p = path_.apices[jb].portal;
    while (p > 0 && (path_.unfolded.portals[p - 1].left_vertex == v || path_.unfolded.portals[p - 1].right_vertex == v))
      --p;
    return p;
  };
  // Around each candidate, out to bends that are not candidates themselves, window_margin faces or
  // more away; windows that overlap are one.
  windows_.clear();
  for (size_t j : candidates_) {
    if (!windows_.empty() && j < windows_.back().jb) continue;
    size_t ja = j - 1, jb = j + 1;
    const int portal = std::clamp(path_.apices[j].portal, 0, n - 1);
    while (ja > 0 && (candidate(ja) || first_after(ja) > portal - options.window_margin)) --ja;
    while (jb < end && (candidate(jb) || last_before(jb) < portal + 1 + options.window_margin)) ++jb;
    if (!windows_.empty() && ja < windows_.back().jb) {
      windows_.back().jb = jb;
    } else {
      windows_.push_back({ja, jb, first_after(ja), 0});
    }
  }
  int faces = 0;
  for (Window& w : windows_) {
    w.last = last_before(w.jb);
    if (w.last <= w.first) return false;  // (a bend that comes back to a vertex of the one before)
    faces += w.last - w.first + 1;
  }
  if (2 * faces > n) return false;
  size_t made = 0;
  for (const Window& w : windows_) {
    if (window_flips_.size() == made) window_flips_.emplace_back();
    made += straighten_window(w.ja, w.jb, w.first, w.last, window_flips_[made], stats);
  }
  if (stats) stats->windows += static_cast<int>(windows_.size());
  // (Nothing shortened: the windows' vertices are frozen now; a whole pass looks at the path next.)
  windows_off_ = true;
  if (made == 0) return true;
  chosen_.clear();
  for (size_t i = 0; i < made; ++i) chosen_.push_back(&window_flips_[i]);
  windows_off_ = !keep_trial(lay_trial(chosen_));
  return true;
}

bool Straightener::straighten_window(size_t ja, size_t jb, int first, int last, Flip& flip, PathStats* stats) {
  const MeshPoint a = ja == 0 ? path_.start : corner_point(mesh_, path_.strip[first], path_.apices[ja].vertex);
  const MeshPoint b =
      jb + 1 == path_.apices.size() ? path_.end : corner_point(mesh_, path_.strip[last], path_.apices[jb].vertex);
  // The path aside while the window's is straightened (frozen vertices stay: the same path there).
  std::swap(path_, outer_);
  path_.start = a, path_.end = b;
  path_.strip.assign(outer_.strip.begin() + first, outer_.strip.begin() + last + 1);
  path_.unfolded.faces.clear(), path_.unfolded.corners.clear(), path_.unfolded.portals.clear();
  append_moved(path_.unfolded, outer_.unfolded, first, last + 1, PlaneMotion{});  // (in the path's plane)
  const double before = path_.length = shorten(path_.unfolded, path_.made, path_.apices, nullptr);
  in_window_ = true;
  for (int passes = 0; passes < options.max_passes; ++passes) {
    if (stats) ++stats->passes;
    if (!pass(stats)) break;
  }
  in_window_ = false;
  // (Flips keep a strip's first and last faces; the layout stays in the plane of the first.)
  const bool shorter = path_.length < before - 1e-12 * mesh_.scale && path_.strip.size() >= 2 &&
                       path_.strip.front() == outer_.strip[first] && path_.strip.back() == outer_.strip[last];
  if (shorter) {
    flip.first = first, flip.last = last, flip.vertex = -1, flip.turn = 0;
    flip.other.assign(path_.strip.begin() + 1, path_.strip.end() - 1);
    flip.laid.assign(path_.unfolded.corners.begin() + 1, path_.unfolded.corners.end() - 1);
    flip.chord = true, flip.chain = false;
  }
  std::swap(path_, outer_);
  return shorter;
}

// =================================================================================================
// Semi-star
// =================================================================================================

bool Straightener::flip(size_t j, double turn, int first, int last, Flip& flip) {
  const int v = path_.apices[j].vertex;
  flip.vertex = v;
  flip.turn = turn;
  flip.chain = flip.chord = false;
  flip.laid.clear();
  if (straight_through(v, turn)) return false;
  const int f0 = path_.strip[first];
  // The run turns around v keeping it on its left or right; the other semi-star the other way.
  const bool run_left = first < last && mesh_.adjacency[f0][edge_around(mesh_, f0, v, true)] == path_.strip[first + 1];
  flip.first = first, flip.last = last;
  flip.other.clear();
  for (int f = f0, steps = 0; steps < 4096; ++steps) {
    f = mesh_.adjacency[f][edge_around(mesh_, f, v, !run_left)];
    if (f < 0) return false;
    if (f == path_.strip[last]) break;
    flip.other.push_back(f);
  }
  double& angle_sum = angle_sums_[v];  // the whole fan: the run and the other side
  if (std::isnan(angle_sum)) {
    angle_sum = 0;
    for (int i = first; i <= last; ++i) angle_sum += corner_angle(mesh_, path_.strip[i], v);
    for (int f : flip.other) angle_sum += corner_angle(mesh_, f, v);
  }
  return !straight_through(v, turn);
}

// =================================================================================================
// Zipper
// =================================================================================================

// A path that runs along a line of mesh vertices on the wrong side of it bends at one of them, v;
// flipping v alone moves the bend to the next vertex of the line, one pass per vertex. The zipper
// replaces the strip faces around all the blocking vertices by the faces on their other side; the
// pass keeps it only if the path gets shorter, otherwise v gets the single flip from then on
// (no_chain_).
void Straightener::zipper(size_t j, Flip& flip, size_t back, size_t ahead, int lo, int hi) {
  const int v = path_.apices[j].vertex, n = static_cast<int>(path_.strip.size());
  if (n < 3 || no_chain_.contains(v)) return;
  const Portal& own = path_.unfolded.portals[std::clamp(path_.apices[j].portal, 0, n - 2)];
  const bool left = own.left_vertex == v;
  if (!left && own.right_vertex != v) return;
  auto side_vertex = [&](int i) {
    return left ? path_.unfolded.portals[i].left_vertex : path_.unfolded.portals[i].right_vertex;
  };
  const Vec2 &from = path_.apices[j - 1].pos, &to = path_.apices[j + 1].pos;
  const bool v_right = orient(from, to, path_.apices[j].pos) < 0;
  auto blocks = [&](int i) {  // the side vertex of portal i
    const double o = orient(from, to, left ? path_.unfolded.left(i) : path_.unfolded.right(i));
    return v_right ? o < 0 : o > 0;
  };
  int first = flip.first, last = flip.last;
  pivots_.clear();
  // (A slide's: every side vertex from v back to the last bend it passes, apex j-back+1, and ahead
  // to apex j+ahead-1; a glide's: every one after portal lo and before portal hi.)
  const int before = lo >= 0 ? lo : path_.apices[j - back].portal;
  const Apex& after = path_.apices[j + ahead];
  const bool all_before = back > 1 || lo >= 0, all_after = ahead > 1 || hi >= 0;
  const int last_back = back > 1 ? path_.apices[j - back + 1].vertex : -1;
  const int last_ahead = ahead > 1 ? path_.apices[j + ahead - 1].vertex : -1;
  for (int i = first - 1; i > before && (all_before || blocks(i));) {  // vertices before v, nearest first
    const int c = side_vertex(i);
    while (i > before + 1 && side_vertex(i - 1) == c) --i;
    pivots_.push_back(c);
    first = i--;
    if (c == last_back) break;
  }
  std::reverse(pivots_.begin(), pivots_.end());  // in strip order
  pivots_.push_back(v);
  const int until = hi >= 0 ? std::min(hi, after.portal) : after.portal;
  for (int i = last; i < std::min(n - 1, until) && (all_after ? side_vertex(i) != after.vertex : blocks(i));) {
    // (vertices after v)
    const int c = side_vertex(i);
    while (i + 1 < n - 1 && side_vertex(i + 1) == c) ++i;
    pivots_.push_back(c);
    last = ++i;
    if (c == last_ahead) break;
  }
  if (pivots_.size() == 1) return;
  // Around each pivot in turn on the side away from the strip, from strip[first] to strip[last].
  // `entry`: the other end of the edge the walk came through (the edge not to cross back over).
  auto around = [&](int f, int pivot, int entry, int& next_entry) {
    const auto& t = mesh_.triangles[f];
    const int k = corner_of(mesh_, f, pivot);
    if (t[(k + 1) % 3] != entry) return next_entry = t[(k + 1) % 3], mesh_.adjacency[f][k];
    return next_entry = t[(k + 2) % 3], mesh_.adjacency[f][(k + 2) % 3];
  };
  const int p0 = pivots_[0];
  int entry = pivots_[1];
  if (contains_vertex(mesh_, path_.strip[first + 1], p0)) {
    const Portal& shared = path_.unfolded.portals[first];
    entry = shared.left_vertex == p0 ? shared.right_vertex : shared.left_vertex;
  }
  std::vector<int>& other = zipper_faces_;
  other.clear();
  size_t at = 0;
  int f = around(path_.strip[first], p0, entry, entry);
  for (int steps = 0;; ++steps) {
    if (f < 0 || steps > 256 + 16 * static_cast<int>(pivots_.size())) return;
    if (at + 1 == pivots_.size()) {
      if (f == path_.strip[last]) break;
    } else if (f == path_.strip[last]) {
      return;
    } else if (contains_vertex(mesh_, f, pivots_[at + 1])) {
      other.push_back(f);
      f = around(f, pivots_[at + 1], pivots_[at], entry);
      ++at;
      continue;
    }
    other.push_back(f);
    f = around(f, pivots_[at], entry, entry);
  }
  flip.first = first, flip.last = last;
  flip.other.swap(other);
  flip.chain = true;
}

// =================================================================================================
// Slide
// =================================================================================================

bool Straightener::turn_about(int x, const Vec2& c, double side, PlaneMotion& m) {
  const double e = angle_sum(x) - 2 * kPi;
  if (std::isnan(e)) return false;
  const double a = side < 0 ? e : -e, ca = std::cos(a), sa = std::sin(a);
  const Vec2 t = c - Vec2(ca * c.x() - sa * c.y(), sa * c.x() + ca * c.y());
  PlaneMotion out;
  out.c = m.c * ca - m.s * sa, out.s = m.s * ca + m.c * sa;
  out.t = m(t);
  m = out;
  return true;
}

bool Straightener::bends_past(int x, double side, const Vec2& in, const Vec2& out) {
  const double c = cross(in, out);
  return c * side > 0 && !std::isnan(angle_sum(x)) && !straight_through(x, std::atan2(std::abs(c), in.dot(out)));
}

bool Straightener::holds_no_bend(int v) { return angle_sum(v) < 2 * kPi + 1e-9; }  // (NaN: false)

double Straightener::angle_sum(int v) {
  double& sum = angle_sums_[v];
  if (std::isnan(sum)) {
    bool closed;
    vertex_fan(mesh_, v, fan_, closed);
    if (!closed) return std::numeric_limits<double>::quiet_NaN();
    sum = 0;
    for (int f : fan_) sum += corner_angle(mesh_, f, v);
  }
  return sum;
}

size_t Straightener::slide(size_t j, size_t& ahead) {
  ahead = 1;
  const size_t count = path_.apices.size();
  const int np = static_cast<int>(path_.unfolded.portals.size());
  const Apex& v = path_.apices[j];
  const double side = cross(v.pos - path_.apices[j - 1].pos, path_.apices[j + 1].pos - v.pos);  // < 0: a right turn
  const bool left = on_left(v);
  auto side_vertex = [&](int i) { return this->side_vertex(left, i); };
  auto side_pos = [&](int i) { return this->side_pos(left, i); };
  const int at = std::clamp(v.portal, 0, np - 1);
  if (side_vertex(at) != v.vertex) return 1;
  auto turn_about = [&](int x, const Vec2& c, PlaneMotion& m) { return this->turn_about(x, c, side, m); };
  // Whether apex d can be passed (only a frozen bend on v's side: the others are flips of their own).
  auto may_pass = [&](size_t d) {
    if (d == 0 || d + 1 >= count) return false;  // (also d "below" 0: j - k wraps round)
    const Apex& x = path_.apices[d];
    return x.vertex >= 0 && on_left(x) == left && frozen_.contains(x.vertex) &&
           (surely_frozen(d) || is_frozen(x.vertex, turn_at(path_.apices, d)));
  };
  // Whether the path, coming into apex d along `in` and leaving along `out`, bends there in v's
  // direction by more than d's excess lets it (d is passed too).
  auto passed = [&](size_t d, const Vec2& in, const Vec2& out) {
    return bends_past(path_.apices[d].vertex, side, in, out);
  };
  // From v along its side of the strip (step -1: back, +1: ahead), turning `m` about every vertex
  // passed; `reached(d)` decides at each apex d = j + step·k whether the slide passes it as well.
  // Returns k for the apex where it stops.
  auto run = [&](int step, PlaneMotion& m, auto&& reached) {
    size_t k = 1;
    if (!may_pass(j + step)) return k;
    int i = at, x = v.vertex, gap = 0;
    Vec2 c = side_pos(at);
    while (turn_about(x, c, m)) {
      while (i >= 0 && i < np && side_vertex(i) == x) i += step;
      if (i < 0 || i >= np) break;
      x = side_vertex(i), c = side_pos(i);
      const size_t d = j + step * static_cast<long>(k);
      if (x != path_.apices[d].vertex) {  // a boundary vertex the path does not touch: passed too
        if (step < 0 ? path_.apices[d].portal >= i : path_.apices[d].portal < i) break;  // d lies on the other side
        if (++gap > options.slide_gap) break;
        continue;
      }
      gap = 0;
      if (!reached(d, m)) break;
      ++k;
      if (!may_pass(j + step * static_cast<long>(k))) break;
    }
    return k;
  };
  // (Not a slide unless it may pass enough bends: most candidates end here, before any angle sum.)
  const size_t least = static_cast<size_t>(std::max(1, options.slide_min));
  size_t may = 0;
  for (size_t k = 1; may < least && may_pass(j - k); ++k) ++may;
  for (size_t k = 1; may < least && may_pass(j + k); ++k) ++may;
  if (may < least) return 1;
  // Back, with the apex after v staying: its layout turns about each vertex passed.
  PlaneMotion back_motion;
  const size_t back = run(-1, back_motion, [&](size_t d, const PlaneMotion& m) {
    return passed(d, path_.apices[d].pos - path_.apices[d - 1].pos, m(path_.apices[j + 1].pos) - path_.apices[d].pos);
  });
  // Ahead, from the apex the path now leaves: the layout beyond each vertex passed turns about it.
  const Vec2 from = path_.apices[j - back].pos;
  PlaneMotion ahead_motion;
  ahead = run(+1, ahead_motion, [&](size_t d, const PlaneMotion& m) {
    const Vec2 here = m(path_.apices[d].pos);
    return passed(d, here - from, m(path_.apices[d + 1].pos) - here);
  });
  if (back + ahead - 2 < least) return ahead = 1;
  return back;
}

bool Straightener::glide(size_t j, int& lo, int& hi) {
  lo = hi = -1;
  const int np = static_cast<int>(path_.unfolded.portals.size());
  const Apex &v = path_.apices[j], &p = path_.apices[j - 1], &q = path_.apices[j + 1];
  const double side = cross(v.pos - p.pos, q.pos - v.pos);  // < 0: a right turn
  const bool left = on_left(v);
  const int at = std::clamp(v.portal, 0, np - 1);
  if (side_vertex(left, at) != v.vertex || holds_no_bend(v.vertex)) return false;
  // From v along its side (step -1: back towards p, +1: ahead towards q) over side vertices the path
  // does not touch, turning the layout beyond each vertex passed about it: the portal of the first
  // vertex where the path would no longer bend (the glide stops before it), or -1 when it passes
  // none or runs into the neighbouring apex (a slide's, or nothing to do).
  auto run = [&](int step) {
    PlaneMotion m;
    int i = at, x = v.vertex, passed = 0;
    Vec2 c = side_pos(left, at);
    while (turn_about(x, c, side, m)) {
      while (i >= 0 && i < np && side_vertex(left, i) == x) i += step;
      if (i < 0 || i >= np || (step < 0 ? i <= p.portal : i >= q.portal)) return -1;
      x = side_vertex(left, i), c = side_pos(left, i);
      const Vec2 here = step < 0 ? c : m(c);  // (ahead, x lies beyond the vertices passed)
      if (holds_no_bend(x) || !bends_past(x, side, here - p.pos, m(q.pos) - here)) return passed > 0 ? i : -1;
      ++passed;
    }
    return -1;
  };
  lo = run(-1), hi = run(+1);
  return lo >= 0 || hi >= 0;
}

// =================================================================================================
// Chord
// =================================================================================================

// A long path first found on the dual graph lies rows of vertices away from the geodesic, and
// semi-star flips move it across one row at a time. So the chord of apex j takes the straight line
// from the neighbouring apex p to the other one, q, in the plane of the strip, and follows it across
// the mesh from p, laying each face it enters flat (a straightest geodesic from p aimed at q), until
// a face holds q. Where the surface between turned the line, it aims once more at where those faces
// put q, or, when the line passed q without meeting it, at where q projects into the plane of the
// face where it did (a long chord over a curved region drifts by more than a face); the second walk
// keeps the first as far as the new line crosses the same edges. The strip then runs around p from
// its faces there to the line, along the line, and around q (on the side the line passes it) to its
// faces there. When the chord fails the pass makes the zipper or semi-star instead; so it does from
// then on for a vertex whose chord did not shorten the path (no_chord_), and while the neighbouring
// apices stay for one whose walk failed (walk_chord: on the knotted tube of BENCHMARKS.md, 40% of
// the failed walks, which enter three times the faces of one that arrives, were such repeats).
bool Straightener::walk_chord(size_t j, const ChordRoom& room, Flip& flip) {
  // Between the same neighbouring apices the line is the same as far as the path's layout between
  // them is; a walk that failed there is not walked again.
  const double between = static_cast<double>(path_.apices[j - 1].vertex) * 4294967296.0 + path_.apices[j + 1].vertex;
  const int v = path_.apices[j].vertex;
  if (const double* failed = failed_chords_.find(v); failed && *failed == between) return false;
  if (chord(j, room, flip)) return true;
  failed_chords_.insert(v, between);
  return false;
}

bool Straightener::chord(size_t j, const ChordRoom& room, Flip& flip) { return chord(j - 1, j + 1, room, flip); }

bool Straightener::chord(size_t jp, size_t jq, const ChordRoom& room, Flip& flip, int aims) {
  const int n = static_cast<int>(path_.strip.size());
  const Apex &p = path_.apices[jp], &q = path_.apices[jq];
  const Vec2 o = p.pos;
  Vec2 d = q.pos - p.pos;
  auto side = [&](const Vec2& c) { return cross(d, c - o); };  // > 0: left of the line
  // The walk: the faces it entered and where it laid them, how many of them it entered turning
  // around p, and the edge it left each face by along the line.
  std::vector<int>& other = walk_faces_;
  std::vector<std::array<Vec2, 3>>& laid = walk_laid_;
  std::vector<int8_t>& exits = walk_exits_;
  size_t around = 0;
  int first = 0, f = path_.strip[0];
  int on_strip = 0;  // strip index of f while the walk follows the strip (its layout is known), else -1
  std::array<Vec2, 3> cf, cg;
  // Where the walk is on the strip after entering face g from strip face `at` (-1: off it).
  auto follow_strip = [&](int at, int g) { return at >= 0 && at + 1 < n && path_.strip[at + 1] == g ? at + 1 : -1; };
  // Into the face across edge e of f. (Every face of a walk goes through it: inlined, f, cf and
  // on_strip stay in registers.)
  auto step = [&](int e) __attribute__((always_inline)) {
    const int g = mesh_.adjacency[f][e];
    if (g < 0) return false;
    on_strip = follow_strip(on_strip, g);
    ++walked_;
    if (on_strip >= 0) {
      cf = path_.unfolded.corners[on_strip];
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
  enum class Trace { kFailed, kReached, kPassed };
  Vec2 at;
  auto passed = [&]() {
    const Vec3 x = q.vertex >= 0 ? mesh_.positions[q.vertex] : eval_position(mesh_, path_.end);
    return lay_point(mesh_, f, cf, x, at) ? Trace::kPassed : Trace::kFailed;
  };
  // Whether the line leaves p through face g laid at c (its corner at p holds the line).
  auto leaves_p = [&](int g, const std::array<Vec2, 3>& c) {
    const int k = corner_of(mesh_, g, p.vertex);
    return side(c[(k + 1) % 3]) < 0 && side(c[(k + 2) % 3]) > 0;
  };
  // Around p, on from its first strip face, to the face whose corner holds the line.
  auto turn_around_p = [&]() {
    other.clear(), laid.clear(), exits.clear();
    first = 0, f = path_.strip[0], on_strip = 0;
    cf = path_.unfolded.corners[0];
    if (p.vertex >= 0) {
      first = room.p_first;
      const bool left = on_left(p);
      f = path_.strip[first];
      cf = path_.unfolded.corners[first];
      on_strip = first;
      for (int steps = 0; !leaves_p(f, cf); ++steps) {
        if (steps > 64 || !step(edge_around(mesh_, f, p.vertex, left)) || f == path_.strip[first]) return false;
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
    for (size_t steps = exits.size(); q.vertex >= 0 ? !contains_vertex(mesh_, f, q.vertex) : f != path_.strip.back();
         ++steps) {
      const int e = exit_edge(cf);
      if (e < 0 || steps > 4 * static_cast<size_t>(n)) return Trace::kFailed;
      if (past_q(cf, e)) return passed();
      exits.push_back(static_cast<int8_t>(e));
      if (!step(e)) return Trace::kFailed;
    }
    at = q.vertex >= 0 ? cf[corner_of(mesh_, f, q.vertex)] : on_face(cf, path_.end);
    return Trace::kReached;
  };
  // The walk along a new d: as far as it takes the same way as the last one (the same turn around
  // p, the same exits from the same faces, laid alike), the last one's; on from where they part.
  auto walk_again = [&]() {
    const std::array<Vec2, 3>* c = &path_.unfolded.corners[first];
    size_t s = 0;
    if (p.vertex >= 0) {
      for (int g = path_.strip[first];; ++s) {
        const bool holds = leaves_p(g, *c);
        if (s == around && holds) break;
        if (s == around || holds) return turn_around_p() ? along() : Trace::kFailed;
        g = other[s], c = &laid[s];
      }
    }
    size_t m = 0;
    for (; m < exits.size() && exit_edge(*c) == exits[m] && !past_q(*c, exits[m]); ++m) c = &laid[s++];
    cf = *c;
    other.resize(s), laid.resize(s), exits.resize(m);
    f = s == 0 ? path_.strip[first] : other[s - 1];
    on_strip = first;
    for (int g : other) on_strip = follow_strip(on_strip, g);
    return along();
  };
  Trace traced = turn_around_p() ? along() : Trace::kFailed;
  // The surface between turned the line: aim again where the line's faces put q (`aims` times at
  // most, while they miss q or reach it off the line).
  auto off = [&]() {
    return traced == Trace::kPassed ||
           (traced == Trace::kReached && std::abs(cross(d, at - o)) > 1e-3 * d.squaredNorm());
  };
  for (int aim = 0; aim < aims && off(); ++aim) {
    if (!((at - o).squaredNorm() > 0)) return false;
    d = at - o;
    traced = walk_again();
  }
  if (traced != Trace::kReached) return false;
  // The path from p to q through the line's faces is at least |at - o| long, so the chord cannot
  // help unless that beats the way by the bends between.
  double way = 0;
  for (size_t k = jp; k < jq; ++k) way += (path_.apices[k + 1].pos - path_.apices[k].pos).norm();
  if ((at - o).norm() >= way) return false;
  int last = n - 1;
  if (q.vertex >= 0) {  // around q, on the side the line passes it, to its strip faces
    const bool left = side(at) > 0;
    for (int steps = 0;; ++steps) {
      int m = room.q_first;
      while (m <= room.q_last && path_.strip[m] != f) ++m;
      if (m <= room.q_last) {
        last = m;
        break;
      }
      if (steps > 64 || !step(edge_around(mesh_, f, q.vertex, left))) return false;
    }
  }
  if (!other.empty() && other.back() == path_.strip[last]) other.pop_back(), laid.pop_back();
  if (last <= first) return false;
  // The line's faces the strip's own (the walk met q's faces early and went round q back to the
  // strip): nothing would change.
  if (other.size() + 1 == static_cast<size_t>(last - first) &&
      std::equal(other.begin(), other.end(), path_.strip.begin() + first + 1))
    return false;
  flip.first = first, flip.last = last;
  flip.other.swap(other);  // (the walk's buffers are scratch: the next walk clears them)
  flip.laid.swap(laid);
  flip.chord = true;
  return true;
}

// =================================================================================================
// Apply
// =================================================================================================

void Straightener::apply(const std::vector<const Flip*>& chosen, std::vector<int>& out, UnfoldedStrip& u,
                         Splice& splice) {
  u.faces.clear(), u.corners.clear(), u.portals.clear();
  splice.path = &path_.made;
  splice.between.clear();
  splice.lo = chosen.front()->first;
  append_moved(u, path_.unfolded, 0, chosen.front()->first + 1, PlaneMotion{});
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
    append_laid(mesh_, u, path_.strip[f.last]);
    moved = PlaneMotion::between(path_.unfolded.corners[f.last], u.corners.back());
    splice.hi = static_cast<int>(u.faces.size()) - 1;
    splice.shift = f.last - splice.hi;
    splice.motion = moved;
    if (i + 1 < chosen.size())  // the portals up to the next change's first face agree
      splice.between.push_back({splice.hi, chosen[i + 1]->first - splice.shift, splice.shift, moved});
    const size_t next = i + 1 < chosen.size() ? chosen[i + 1]->first + 1 : path_.strip.size(), joint = u.faces.size();
    append_moved(u, path_.unfolded, f.last + 1, next, moved);
    join(mesh_, u, joint);
  }
  out.assign(u.faces.begin(), u.faces.end());
  // A new face may also be one the strip keeps elsewhere (or another flip's): then the strip has a
  // loop to cut, and the faces after it are laid anew.
  constexpr int kNew = -2;
  size_t added = 0, seen = 0;
  bool repeated = false;
  for (const Flip* f : chosen)
    for (int face : f->other) repeated |= face_marks_[face] == kNew, face_marks_[face] = kNew, ++added;
  for (int face : out) seen += face_marks_[face] == kNew;
  for (const Flip* f : chosen)
    for (int face : f->other) face_marks_[face] = -1;
  if (repeated || seen != added) {
    splice.path = nullptr;
    remove_loops(out, face_marks_);
    unfold_strip(mesh_, out, u, &path_.unfolded);
  }
}

}  // namespace splinekit::surface
