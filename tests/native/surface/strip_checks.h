// Checks on face strips shared by the straightening's tests (straighten_test.cpp, aim_test.cpp).
#pragma once

#include "surface/mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace splinekit::surface::testing {

inline MeshPoint centroid(int face) { return {face, Vec2(1.0 / 3, 1.0 / 3)}; }

// Consecutive faces share an edge and no face comes twice.
inline void expect_strip(const TriMesh& mesh, const std::vector<int>& strip) {
  for (size_t i = 0; i + 1 < strip.size(); ++i)
    EXPECT_GE(edge_to(mesh, strip[i], strip[i + 1]), 0) << "faces " << i << ", " << i + 1;
  std::vector<int> sorted = strip;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end()) << "a face twice";
}

}  // namespace splinekit::surface::testing
