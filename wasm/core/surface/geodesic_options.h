// The options and counters of locally shortest paths (geodesic.h): what each phase reads and what
// it counts. Defaults and the measurements behind them: BENCHMARKS.md, "Why these defaults".
#pragma once

namespace splinekit::surface {

// Which graph phase (i) searches. kRefined (edge nodes, distances along straight runs through
// windows, the queue drained under the A* bound) finds the strip of the globally shortest path far
// more often; kDual (face nodes only, stopping at the first arrival, as in the paper) is several times
// cheaper and is what curve tracing uses, where most paths are short and start from nearby points.
enum class SearchGraph { kRefined, kDual };

struct ShortestPathOptions {
  // ---- Phase (iii), the straightening (straighten.h) ----
  bool straighten = true;        // run phase (iii) at all (else the funnel path of the initial strip)
  bool chords = true;            // flips along the line between apices (else semi-stars and zippers only)
  double chord_min_turn = 0.03;  // radians: a chord only where the path turns by more (else a semi-star)
  bool slides = true;            // a bend that would slide along a row of saddle vertices is moved at once
  int slide_min = 4;             // ... when that passes at least this many bends (else a pass moves it)
  int slide_gap = 2;             // a slide passes at most this many untouched vertices between two bends
  // A bend against a row of saddle vertices the path does not touch glides along it at once, to the
  // vertex where it fades (Straightener::glide), where each flip moved it a vertex (on the knotted
  // tube of the benchmarks a bend of 0.1 rad against vertices of excess 0.0018 took 35 passes to
  // fade). Tried where a chord is not. 2026-12-07, native, 40 random curves, interleaved, with and
  // without: knotted tube 0.66x the time (0.71x the passes), folded body 0.93x, coil 0.98x, UV sphere
  // 1.00x, nefertiti 1.01x, spot_loop2_369k 1.045x (as many passes: its glides seldom pass a vertex,
  // and working them out costs angle sums); the same sides. Rows of any vertices (convex ones too,
  // which a bend always passes): nefertiti's sides other local geodesics more often (-0.07% in total).
  bool glides = true;
  int max_passes = 100000;  // safety bound on phase (iii)'s passes (each flips several vertices)
  // A run of at least span_min_bends consecutive bends of the path at vertices that cannot hold one
  // (angle sum at most 2π: on a convex or flat stretch a locally shortest path bends nowhere) is
  // crossed at once by the chord from the apex before the run to the one after it (a span,
  // Straightener::span_pass), aimed again up to span_aims times where the surface turned the line,
  // before the pass flips vertices; a path stops trying after span_failures spans that did not
  // shorten it (0 for span_min_bends, or no chords: never). Where faces are long and thin across the
  // way, each flip moves the strip by one row and the bends slide across the rows a vertex per pass
  // (the UV sphere of the benchmarks: a 2.3-long side took 172 passes, with spans 12). 2026-12-07,
  // native, 40 random curves, interleaved: the UV sphere 0.63x the time, the folded body 0.88x (its
  // limbs are cylinders: flat), the knotted tube 0.97x, the others within 3%; the three sides of the
  // curves as long in total (within 0.04%; on nefertiti a few go another way, up to 3.5% longer or
  // shorter, as many each way). On 90 long sides alone: aimed again once (as the chords) the sphere's
  // took 0.85x the time, four times 0.83x, eight 0.52x (a span across a long side misses the end's
  // face without more); with bends at saddle vertices in the runs too, the knotted tube's 1.6x and the
  // coil's 1.9x (the lines pass over the tube's inner side and come out longer).
  int span_min_bends = 2;
  int span_aims = 8;
  int span_failures = 2;
  // A pass on a strip of at least window_min_faces faces (0: never) whose reflex vertices lie in
  // short stretches straightens each stretch on its own: the faces from a bend of the path at least
  // window_margin faces before it to one as far after (Straightener::windowed_pass). On the
  // benchmark's coil the long paths' last passes slide bends along the saddle vertices of the tube's
  // inner side in three or four places at once, a vertex or two per pass, each pass costing the
  // whole strip (2026-12-05: 0.63x native instructions there, the same paths; the knotted tube and
  // folded body 0.96x and 1.00x: their paths bend at a few vertices, nearly all moving at once, so
  // the windows would cover the strip; 64 and 1024 against 128 and 2048: 0.63x against 0.65x).
  int window_min_faces = 1024;
  int window_margin = 64;
  // ---- Phase (i), the search (dual_search.h) ----
  double long_edge_fraction = 0.0075;  // edges longer than this fraction of the bounding-box diagonal
                                       // get one graph node per such length
  int steiner = 2;                     // graph nodes on every edge
  double dual_heuristic_weight = 3;    // weight of the A* Euclidean term in the kDual search
  // ... at least this many times the dual graph's stretch (0: never), DualSearch::dual_stretch(). Across
  // long thin faces a path from centroid to centroid zigzags: along the short side of a quad split in
  // two it runs about 2/3 of the long side per quad crossed. Where that stretch passes the weight, the
  // distance grows faster along the way than the A* term falls, and the greedy search expands all it
  // can reach (2026-12-05, native, 40 random curves, interleaved: a UV sphere of 2000 x 150 quads, 7:1
  // at the equator and thinner towards the poles, stretch 20.1, weight 25: 0.64x the time, 0.09x the
  // nodes, the same curves; the knotted tube 5.2: 0.965x; the folded body 6.8: 0.996x; the meshes
  // whose faces are near regular measure 1.3-1.8 and keep the weight).
  double dual_stretch_weight = 1.25;
  // A kDual strip of at least this many faces is searched again from b to a, and the strip whose
  // funnel path is shorter is straightened (0: never): the greedy search's strip depends on the end
  // it starts from, and the straightening's work grows with the region between strip and geodesic.
  int dual_reverse_search_faces = 512;
  // Such a strip also gets a candidate that follows the surface's shortest way (needs landmarks): down
  // the distance field of the landmark that bounds the distance between the ends best, from the end
  // farther from it to where the field is level with the other end, then the greedy search on to that
  // end (Landmarks::descend); when it beats the forward strip, the search from the far end is left out.
  // On a coiled tube the geodesic between far points runs along the tube's
  // inner side, which the dual-graph distances from far away follow, while the greedy strip keeps to
  // the side it started on and the flips sweep the whole band between (BENCHMARKS.md, "Surface at
  // scale", Landmark descent).
  bool landmark_descent = true;
  // ... unless the descent ends farther than this share of the best candidate's funnel length (in space)
  // from the other end: there the landmark's way passes elsewhere (on the folded body, along another
  // limb; 2026-12-04: without it, its curves took 1.1-1.2 times as long, none shorter).
  double landmark_descent_gap = 0.05;
  // A kDual path whose ends lie at least this many of a coarse guide's mean edge lengths apart (in space
  // or by the landmarks' bound) and whose path on the guide crosses at least as many of its faces gets
  // its strip from that path (coarse_guide.h; 0: never): on the coil, the knotted tube and the folded
  // body the long sides' strips then lie near the geodesic, where the greedy search's keep to one side
  // of the tube or limb and the straightening sweeps the band between (BENCHMARKS.md, "Surface at
  // scale", Coarse guide). Only with a guide (GeodesicSolver::set_coarse_guide).
  int coarse_guide_faces = 24;
  // The strip follows the guide's path by walking its segments across the faces (CoarseGuide::walks)
  // where the median face's longest edge is more than this many times its shortest (0: never), else
  // by descending towards its points face by face: on long thin faces the nearest centroid misleads
  // (2026-12-05, 30 random curves, native: the knotted tube's faces, about 6:1, 0.73x the time
  // walking; the folded body's, about 18:1, 0.96x; on the coil, about 1.3:1, walking took 1.10x,
  // spot_loop2_369k 1.07x: a strip one face wide leaves the bends to move a row a pass).
  double guide_walk_aspect = 3;
  // A kRefined search between ends as far apart (coarse_guide_faces) keeps to the guide's corridor of
  // ways at most this much longer than its shortest (CoarseGuide::corridor; 0: the whole mesh). The
  // search's Euclidean term knows nothing of the surface, and its landmark term (refined_landmark_share)
  // bounds only part of the way, so on a tube it floods the tube between the ends. The slack covers
  // how far the guide's lengths stray from the mesh's: 2026-12-05, native, random vertex pairs,
  // against the whole mesh's search (interleaved; "worse": more than 0.5% longer than its path):
  // 0.04: knotted tube 0.74x (80 pairs, none worse), coil 0.63x (20 pairs); 0.02: coil 0.6x, nefertiti 0.75x,
  // but one of the knotted tube's 80 pairs 3.9% longer (its guide has six vertices round the tube)
  // and in the benchmark 98 of its 100 within 0.5% of exact; 0.01: folded body 0.43x, spot 0.53x,
  // noisy spot 0.51x, one of nefertiti's 40 worse. Tried: a corridor 2 guide edges wide around the
  // guide's one path: the coil 0.24x, but 4 of the knotted tube's 40 pairs and 3 of spot's took the
  // other way round (up to 2.7% longer); coarse distances along edges alone (no fast-marching
  // update): at 0.01 two of the noisy spot's 40 and one of the folded body's worse (up to 2%).
  // Off by default (0): alone, the share missed on short ways (in the benchmark, wasm, 100 pairs a
  // mesh against exact, one of the knotted tube's paths came out 9.6% longer, 98 of 100 within 0.5%,
  // 100 without); with guide_corridor_edges of the guide's mean edges more (0.04 and 1: the knotted
  // tube 100 of 100, 0.60x the whole mesh's time, the coil 0.71x, the folded body 0.48x) the folded
  // body still had 97 within 0.5% against 99 without (BENCHMARKS.md, "Surface at scale").
  double guide_corridor_slack = 0;
  double guide_corridor_edges = 1;
  // Landmark lower bounds (landmarks.h) in components of at least landmark_min_faces faces: the A* term
  // is the larger of the Euclidean one and the landmark one, weighted by landmark_weight in the kDual
  // search (where the bound is admissible) and, in the kRefined one, by refined_landmark_scale when
  // that is above 0, else by refined_landmark_share / DualSearch::dual_stretch(). A landmark bound is
  // one on the dual graph's distance, which runs longer than the surface's by about the graph's
  // stretch, so the bound divided by the stretch is one on the surface's distance, and so on the
  // refined graph's (never shorter than the surface's); the stretch is a 90th percentile over short
  // distances (where the graph's zigzag weighs most), and the share keeps a margin below it. The term
  // is used only in a search whose ends it bounds farther apart than space does (on a tube, a coil,
  // a fold; elsewhere it seldom beats the Euclidean term, and its look-ups cost 7-8% of the search).
  // 2026-12-07, native, 40 random vertex pairs per mesh against the Euclidean term alone, interleaved
  // (">0.5%": paths more than 0.5% longer than its): share 0.75: knotted tube 0.84x the time (none
  // >0.5%, 2 shorter), coil 0.84x (none), folded body 0.98x (none, 6 shorter), the meshes whose
  // searches leave it out within 1%; share 1: knotted tube 0.71x but 4 of 40 >0.5% (up to 1.13%),
  // folded body 0.80x and one 0.53% longer (both without the gate). Before: an absolute scale of
  // 0.85 made the search ~40 times cheaper on that coil (2026-12-02, before windows) but only 90% of
  // nefertiti's paths stayed within 0.5% of the exact distance (BENCHMARKS.md, "Surface at scale"). Also tried for the
  // refined search (2026-12-02, on the 384k-triangle coil): landmark distances on a "collapsed" refined graph (one node
  // per edge for its Steiner nodes, links the nearest node pairs: never longer than the refined graph, so admissible)
  // bound only ~0.4 of the distance and expanded as many nodes; on the refined graph itself (exact, consistent only up
  // to moving the face's value to the node) the precompute took 1.2 s for 8 landmarks on a 25.6k-triangle coil, and the
  // A* had to reopen nodes to stay exact (more expansions than without); a vertex potential made 1-Lipschitz per face
  // by lowering vertices does not converge (lowering one face's vertex steepens its neighbours'); a corridor around the
  // dual graph's shortest path misses the geodesic on grid-like meshes (dual shortest paths wander across a band of
  // equal-length staircases), giving longer paths.
  int landmarks = 8;                     // landmarks per mesh (2 bytes per face each); 0: none
  int landmark_min_faces = 16384;        // smaller components get none: they search fast enough on the
                                         // Euclidean term
  double landmark_weight = 2;            // kDual (as dual_heuristic_weight: a greedy search)
  double refined_landmark_scale = 0;     // kRefined: an absolute weight (tests), overrides the share
  double refined_landmark_share = 0.75;  // kRefined: the weight as a share of 1 / dual_stretch()
};

// Counters for tests and benchmarks, summed over the calls they are passed to.
struct PathStats {
  int searches = 0;         // phase (i): searches run (shortest_path calls that searched)
  int visited_nodes = 0;    // phase (i): graph nodes taken from the queue and expanded
  int strip_faces = 0;      // phase (ii): faces of the strips laid out and straightened
  int passes = 0;           // phase (iii): straightening passes
  int accepted_flips = 0;   // phase (iii): flips (semi-star, zipper or chord) kept because they shortened the path
  int frozen_vertices = 0;  // phase (iii): vertices found locally shortest (or not flippable) and frozen
  int chords_tried = 0;     // phase (iii): chords traced (walks along the line between two apices)
  int chords_kept = 0;      // phase (iii): of the kept flips, chords
  int walked_faces = 0;     // phase (iii): faces the chords' walks entered (kept or not)
  int pass_faces = 0;       // phase (iii): faces of the strips the passes worked on (a window's its own)
  int windows = 0;          // phase (iii): windows straightened on their own
  int guided = 0;           // phase (i): strips followed from a coarse guide's path

  PathStats& operator+=(const PathStats& o) {
    searches += o.searches, visited_nodes += o.visited_nodes, strip_faces += o.strip_faces, passes += o.passes;
    accepted_flips += o.accepted_flips, frozen_vertices += o.frozen_vertices;
    chords_tried += o.chords_tried, chords_kept += o.chords_kept, walked_faces += o.walked_faces;
    pass_faces += o.pass_faces, windows += o.windows, guided += o.guided;
    return *this;
  }
};

}  // namespace splinekit::surface
