#pragma once
// A progressive mesh (paper §4, after Hoppe, "Progressive meshes", SIGGRAPH 1996): a
// garment as its coarsest level plus the vertex splits that rebuild it, coarsest first.
// Each split is the inverse of one edge collapse of the decimation (Decimation.h):
//
//   collapse: `added` joins `kept`, which moves (at rest) from keptRest to collapsedRest;
//             the faces on the edge go, the faces of `added` take `kept` instead;
//   split:    the reverse: `added` comes back at addedRest, `kept` returns to keptRest,
//             the faces come back with their corners, the re-pointed faces take `added`.
//
// Vertices and faces keep the full garment's numbering at every level, so a level is a
// choice of which are active (MeshLevel).

#include <vector>

#include "sim/core/TriangleMesh.h"

namespace figment {

struct RestoredFace {
  int face;          // index in the full garment
  Triangle corners;  // its corners at the finer level (vertices active there)
};

struct VertexSplit {
  int kept = -1, added = -1;
  Vec3 keptRest, addedRest, collapsedRest;  // m, rest positions
  std::vector<RestoredFace> restored;       // the faces on the collapsed edge (1 or 2)
  std::vector<int> repointed;               // faces whose corner goes back from kept to added
};

struct ProgressiveMesh {
  TriangleMesh full;                // the garment, rest shape, all levels' numbering
  std::vector<VertexSplit> splits;  // coarsest first: level k = the coarsest + k splits

  int levels() const { return static_cast<int>(splits.size()); }
};

// One level of a progressive mesh, moved up and down by splits and collapses.
class MeshLevel {
 public:
  // The coarsest level (every split undone).
  explicit MeshLevel(const ProgressiveMesh& mesh);

  int level() const { return level_; }
  // Applies splits until level() == target (up only); returns the vertices added.
  std::vector<int> splitTo(int target);
  // The active vertices and faces as a compact mesh (rest positions), and each compact
  // vertex's index in the full garment.
  TriangleMesh restMesh(std::vector<int>& fullIndex) const;
  bool vertexActive(int v) const { return vertexActive_[v]; }
  const Vec3& rest(int v) const { return rest_[v]; }
  const Triangle& corners(int face) const { return corners_[face]; }
  // The active faces around an active vertex.
  const std::vector<int>& facesOf(int v) const { return faces_[v]; }
  bool faceActive(int face) const { return faceActive_[face]; }
  int activeFaces() const;
  int activeVertices() const;

 private:
  void collapse(const VertexSplit& split);
  void split(const VertexSplit& split);

  const ProgressiveMesh& mesh_;
  int level_ = 0;
  std::vector<char> vertexActive_, faceActive_;
  std::vector<Vec3> rest_;
  std::vector<Triangle> corners_;
  std::vector<std::vector<int>> faces_;  // per vertex, its active faces
};

}  // namespace figment
