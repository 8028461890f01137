// splinekit — a 2D triangle mesh viewed in caller-owned flat arrays: the domain on which the
// skinning weights (weights.h), their operators (operators.h) and point location
// (point_location.h) work.
#pragma once

#include <cstddef>
#include <cstdint>

#include "common/geometry.h"

namespace splinekit::skin {

// A 2D triangle mesh in caller-owned flat arrays (no ownership, no copy). Triangles may have
// either orientation.
struct MeshView2 {
  const double* vertices = nullptr;    // #V by 2: x,y
  int vertex_count = 0;                // #V
  const int32_t* triangles = nullptr;  // #F by 3: vertex indices
  int triangle_count = 0;              // #F

  // The x,y of vertex v (2 doubles).
  const double* vertex(int v) const { return vertices + 2 * size_t(v); }
  // The position of vertex v.
  Vec2 position(int v) const { return vec2_at(vertices, v); }
  // The 3 vertex indices of triangle t.
  const int32_t* triangle(int t) const { return triangles + 3 * size_t(t); }
};

// A triangulated surface in 3D, the same way (vertices: #V by 3: x,y,z). The bounded biharmonic
// weights of subdivision surfaces (skin3d/weights.h) run on it.
struct MeshView3 {
  const double* vertices = nullptr;    // #V by 3: x,y,z
  int vertex_count = 0;                // #V
  const int32_t* triangles = nullptr;  // #F by 3: vertex indices
  int triangle_count = 0;              // #F

  Vec3 position(int v) const {
    return {vertices[3 * size_t(v)], vertices[3 * size_t(v) + 1], vertices[3 * size_t(v) + 2]};
  }
  const int32_t* triangle(int t) const { return triangles + 3 * size_t(t); }
};

}  // namespace splinekit::skin
