#include "sim/progressive/ProgressiveMesh.h"

#include <stdexcept>
#include <string>

namespace figment {

MeshLevel::MeshLevel(const ProgressiveMesh& mesh)
    : mesh_(mesh),
      level_(mesh.levels()),
      vertexActive_(mesh.full.vertices.size(), 1),
      faceActive_(mesh.full.triangles.size(), 1),
      rest_(mesh.full.vertices),
      corners_(mesh.full.triangles),
      faces_(mesh.full.vertices.size()) {
  for (int f = 0; f < static_cast<int>(corners_.size()); ++f)
    for (int v : corners_[f]) faces_[v].push_back(f);
  for (int k = mesh.levels() - 1; k >= 0; --k) collapse(mesh.splits[k]);
  level_ = 0;
}

void MeshLevel::collapse(const VertexSplit& s) {
  for (const RestoredFace& f : s.restored) {
    faceActive_[f.face] = 0;
    for (int v : corners_[f.face]) std::erase(faces_[v], f.face);
  }
  for (int f : s.repointed) {
    for (int& corner : corners_[f])
      if (corner == s.added) corner = s.kept;
    faces_[s.kept].push_back(f);
  }
  faces_[s.added].clear();
  vertexActive_[s.added] = 0;
  rest_[s.kept] = s.collapsedRest;
}

void MeshLevel::split(const VertexSplit& s) {
  vertexActive_[s.added] = 1;
  rest_[s.added] = s.addedRest;
  rest_[s.kept] = s.keptRest;
  for (int f : s.repointed) {
    for (int& corner : corners_[f])
      if (corner == s.kept) corner = s.added;
    std::erase(faces_[s.kept], f);
    faces_[s.added].push_back(f);
  }
  for (const RestoredFace& f : s.restored) {
    faceActive_[f.face] = 1;
    corners_[f.face] = f.corners;
    for (int v : f.corners) faces_[v].push_back(f.face);
  }
}

std::vector<int> MeshLevel::splitTo(int target) {
  if (target < level_ || target > mesh_.levels())
    throw std::invalid_argument("level " + std::to_string(target) + " is not in [" + std::to_string(level_) + ", " +
                                std::to_string(mesh_.levels()) + "]");
  std::vector<int> added;
  for (; level_ < target; ++level_) {
    split(mesh_.splits[level_]);
    added.push_back(mesh_.splits[level_].added);
  }
  return added;
}

TriangleMesh MeshLevel::restMesh(std::vector<int>& fullIndex) const {
  TriangleMesh out;
  std::vector<int> compact(rest_.size(), -1);
  fullIndex.clear();
  for (size_t v = 0; v < rest_.size(); ++v)
    if (vertexActive_[v]) {
      compact[v] = static_cast<int>(fullIndex.size());
      fullIndex.push_back(static_cast<int>(v));
      out.vertices.push_back(rest_[v]);
    }
  for (size_t f = 0; f < corners_.size(); ++f)
    if (faceActive_[f])
      out.triangles.push_back({compact[corners_[f][0]], compact[corners_[f][1]], compact[corners_[f][2]]});
  return out;
}

int MeshLevel::activeFaces() const {
  int count = 0;
  for (char active : faceActive_) count += active;
  return count;
}

int MeshLevel::activeVertices() const {
  int count = 0;
  for (char active : vertexActive_) count += active;
  return count;
}

}  // namespace figment
