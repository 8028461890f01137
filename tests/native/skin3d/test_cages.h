// Quad cages for the skin3d tests: OBJ files of ../shared/data (v, f and OpenSubdiv `t crease`
// tags) and small generated ones.
#pragma once

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "skin3d/poly_mesh.h"
#include "skin3d/subdivision.h"

namespace splinekit::skin3d::test_cages {

struct Cage {
  std::vector<double> V;  // #V by 3
  std::vector<int> sizes, indices;
  std::vector<Crease> creases;
  std::vector<Corner> corners;
  int nv() const { return int(V.size() / 3); }
  int nf() const { return int(sizes.size()); }
  PolyMesh mesh() const {
    PolyMesh m;
    const std::string e = make_poly_mesh(nv(), sizes.data(), nf(), indices.data(), m);
    if (!e.empty()) throw std::runtime_error(e);
    const std::string c = apply_creases(creases.data(), int(creases.size()), m);
    if (!c.empty()) throw std::runtime_error(c);
    const std::string k = apply_corners(corners.data(), int(corners.size()), m);
    if (!k.empty()) throw std::runtime_error(k);
    return m;
  }
};

// The shared test data folder (../shared/data next to the repository).
inline std::string shared_data(const std::string& relative) {
  std::string here = __FILE__;  // <repo>/tests/native/skin3d/test_cages.h
  for (int i = 0; i < 4; ++i) here = here.substr(0, here.find_last_of('/'));
  return here + "/../shared/data/" + relative;
}

inline Cage read_cage(const std::string& name) {
  std::ifstream in(shared_data("meshes/quad/" + name));
  if (!in) throw std::runtime_error("cannot open " + name);
  Cage c;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string tag;
    s >> tag;
    if (tag == "v") {
      double x, y, z;
      s >> x >> y >> z;
      c.V.insert(c.V.end(), {x, y, z});
    } else if (tag == "f") {
      std::string corner;
      int n = 0;
      while (s >> corner) c.indices.push_back(std::stoi(corner) - 1), ++n;
      c.sizes.push_back(n);
    } else if (tag == "t") {
      std::string kind, counts;
      s >> kind >> counts;
      if (kind != "crease") continue;
      Crease k;
      s >> k.a >> k.b >> k.sharpness;
      c.creases.push_back(k);
    }
  }
  return c;
}

// An n by m grid of unit quads in the plane z = 0 (an open sheet with a boundary and 4 corners).
inline Cage sheet(int n, int m) {
  Cage c;
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= n; ++i) c.V.insert(c.V.end(), {double(i), double(j), 0.0});
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i;
      c.indices.insert(c.indices.end(), {a, a + 1, a + n + 2, a + n + 1});
      c.sizes.push_back(4);
    }
  return c;
}

// M · V (#refined by 3) for a cage at `levels`.
inline std::vector<double> refine(const Cage& c, int levels) {
  Subdivision s;
  s.build(c.mesh(), levels);
  std::vector<double> out(3 * size_t(s.refined_vertex_count()));
  s.apply(c.V.data(), 3, out.data());
  return out;
}

inline const char* const kSharedCages[] = {"cube_quad.obj",
                                           "torus_quad.obj",
                                           "blub_control_mesh.obj",
                                           "spot_control_mesh.obj",
                                           "catmark_car.obj",
                                           "catmark_cube_creases0.obj",
                                           "catmark_cube_creases1.obj",
                                           "catmark_pawn.obj"};

}  // namespace splinekit::skin3d::test_cages
