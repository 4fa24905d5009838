#pragma once
// MakeHuman's skeleton (MPFB2's "standard" rig, CC0) over its base mesh: each bone's head
// and tail are placed from the morphed mesh's vertices (a joint cube's centre, a vertex, or
// the mean of a few), so the joints follow whatever body the targets made; each bone
// carries skinning weights on the file's vertices. Read by io/MakeHumanRig.h; this is the
// data and the placement, Eigen only.

#include <string>
#include <utility>
#include <vector>

#include "sim/core/TriangleMesh.h"

namespace figment {

// Where a joint sits: the mean of these file vertices (a joint cube's eight, one vertex,
// or the two a "MEAN" names).
struct RigJointPlace {
  std::vector<int> vertices;
};

struct RigBone {
  std::string name;  // e.g. "upperarm01.L" (.L: the body's left, +x)
  int parent = -1;   // index into HumanRig::bones, before this one; -1: the root
  RigJointPlace head, tail;
  std::vector<std::pair<int, double>> weights;  // (file vertex, weight); a vertex's sum to 1
};

struct PlacedBone {
  Vec3 head, tail;
};

class HumanRig {
 public:
  // Throws std::invalid_argument when a parent does not come before its child, or a
  // joint names no vertex or one at or beyond `fileVertexCount`, or a weight is not finite.
  HumanRig(std::vector<RigBone> bones, int fileVertexCount);

  const std::vector<RigBone>& bones() const { return bones_; }
  // The bone's index, -1 when the rig has none so named.
  int find(const std::string& name) const;
  // Index of `name`; throws std::invalid_argument("no bone 'name'") when absent.
  int require(const std::string& name) const;
  int fileVertexCount() const { return fileVertexCount_; }

  // Heads and tails on a body whose file vertices are `fileVertices` (HumanModel::
  // fileVertices). Throws std::invalid_argument when their count is not fileVertexCount().
  std::vector<PlacedBone> place(const std::vector<Vec3>& fileVertices) const;

 private:
  std::vector<RigBone> bones_;
  int fileVertexCount_ = 0;
};

}  // namespace figment
