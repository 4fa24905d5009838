#pragma once
// The connectivity the decimation keeps while it collapses edges: each vertex's active
// faces, each face's current corners, and the rest positions of the current level.

#include <vector>

#include "sim/core/TriangleMesh.h"

namespace figment {

class CollapseNeighbourhood {
 public:
  explicit CollapseNeighbourhood(const TriangleMesh& mesh);

  const Vec3& rest(int v) const { return rest_[v]; }
  const Triangle& corners(int f) const { return corners_[f]; }
  const std::vector<int>& faces(int v) const { return faces_[v]; }
  bool active(int v) const { return active_[v]; }
  int activeFaces() const { return activeFaces_; }

  // The vertices sharing a face with v (each once, v excluded).
  std::vector<int> ring(int v) const;
  // The faces holding both a and b.
  std::vector<int> edgeFaces(int a, int b) const;
  // An edge is on the boundary when one face holds it; a vertex when one of its edges is.
  bool boundaryEdge(int a, int b) const { return edgeFaces(a, b).size() == 1; }
  bool boundaryVertex(int v) const;

  // Removes the faces holding both, moves `removed`'s faces to `kept`, puts kept at
  // `position`. Returns the faces re-pointed from removed to kept.
  std::vector<int> collapse(int kept, int removed, const Vec3& position);

 private:
  std::vector<Vec3> rest_;
  std::vector<Triangle> corners_;
  std::vector<std::vector<int>> faces_;  // per vertex, its active faces
  std::vector<char> active_;
  int activeFaces_ = 0;
};

}  // namespace figment
