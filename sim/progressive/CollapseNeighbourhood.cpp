#include "sim/progressive/CollapseNeighbourhood.h"

#include <algorithm>

namespace figment {

CollapseNeighbourhood::CollapseNeighbourhood(const TriangleMesh& mesh)
    : rest_(mesh.vertices),
      corners_(mesh.triangles),
      faces_(mesh.vertices.size()),
      active_(mesh.vertices.size(), 1),
      activeFaces_(static_cast<int>(mesh.triangles.size())) {
  for (int f = 0; f < static_cast<int>(mesh.triangles.size()); ++f)
    for (int v : mesh.triangles[f]) faces_[v].push_back(f);
}

std::vector<int> CollapseNeighbourhood::ring(int v) const {
  std::vector<int> out;
  for (int f : faces_[v])
    for (int c : corners_[f])
      if (c != v && std::find(out.begin(), out.end(), c) == out.end()) out.push_back(c);
  return out;
}

std::vector<int> CollapseNeighbourhood::edgeFaces(int a, int b) const {
  std::vector<int> out;
  for (int f : faces_[a]) {
    const Triangle& c = corners_[f];
    if (c[0] == b || c[1] == b || c[2] == b) out.push_back(f);
  }
  return out;
}

bool CollapseNeighbourhood::boundaryVertex(int v) const {
  for (int n : ring(v))
    if (boundaryEdge(v, n)) return true;
  return false;
}

std::vector<int> CollapseNeighbourhood::collapse(int kept, int removed, const Vec3& position) {
  const std::vector<int> gone = edgeFaces(kept, removed);
  for (int f : gone) {
    for (int c : corners_[f]) std::erase(faces_[c], f);
    --activeFaces_;
  }
  std::vector<int> repointed = faces_[removed];
  for (int f : repointed) {
    for (int& c : corners_[f])
      if (c == removed) c = kept;
    faces_[kept].push_back(f);
  }
  faces_[removed].clear();
  active_[removed] = 0;
  rest_[kept] = position;
  return repointed;
}

}  // namespace figment
