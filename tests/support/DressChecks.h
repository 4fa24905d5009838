#pragma once
// Checks on a generated strap dress (sim/garment/StrapDress.h), shared by the tests on the box figure
// and on the default body.

#include <set>
#include <vector>

#include "sim/garment/StrapDress.h"
#include "support/MeshChecks.h"

namespace figment::checks {

inline bool onStrap(const StrapDress& dress, int triangle) {
  return triangle >= dress.tubeTriangles;
}

// The tube's top edge: the vertices on edges that one tube triangle uses, above the hem.
inline std::vector<Vec3> tubeTopEdge(const StrapDress& dress) {
  TriangleMesh tube;
  tube.vertices = dress.mesh.vertices;
  tube.triangles.assign(dress.mesh.triangles.begin(), dress.mesh.triangles.begin() + dress.tubeTriangles);
  std::set<int> top;
  for (const auto& [edge, count] : edgeUses(tube))
    if (count == 1)
      for (int v : {edge.first, edge.second})
        if (tube.vertices[v].y() > dress.hemHeight + 1e-9) top.insert(v);
  std::vector<Vec3> out;
  for (int v : top) out.push_back(tube.vertices[v]);
  return out;
}

}  // namespace figment::checks
