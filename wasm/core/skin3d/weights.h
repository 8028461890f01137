// splinekit — bounded biharmonic weights on a subdivision surface (Jacobson, Baran, Popović &
// Sorkine 2011; the 2D solver of skin/weights.h run with the surface's operators).
//
// The weights are solved on the level-l refinement of the cage (l ≤ the rig's level k; the
// triangulated level-l quads with their 3D cotangent Laplacian and lumped mass), each point handle
// snapped to its nearest level-l vertex, and then carried to level k by the subdivision steps
// S_{l+1} … S_k. Catmull-Clark masks are non-negative and sum to 1, so the prolongated weights
// stay in [0, 1] and a partition of unity; solving on a coarser level keeps large cages fast.
#pragma once

#include <string>
#include <vector>

#include "skin/weights.h"
#include "skin3d/rig.h"

namespace splinekit::skin3d {

// Fills rig.refined_weights() (and rig.cage_weights(): each cage vertex's descendant) with BBW of
// the handles (#H by 3, rig.handle_count() of them) solved at `level` (0 = the cage itself, fanned
// into triangles, ..., rig.levels()). Returns a report whose error names the problem (level out of
// range, two handles snapping to the same vertex, a part of the surface without a handle).
skin::WeightsReport surface_bbw_weights(SubdivisionRig& rig, const double* handles, int level,
                                        const skin::BbwOptions& options);

// The level of a rig at which surface_bbw_weights keeps at most `max_vertices` vertices (at least 0).
int bbw_level(const SubdivisionRig& rig, int max_vertices);

}  // namespace splinekit::skin3d
