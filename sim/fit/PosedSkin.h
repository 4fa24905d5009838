#pragma once
// A body's skin in its rest pose and in a pose (the same triangles, each vertex moved by
// the rig: a posed HumanBody keeps its vertices' numbers), so that a garment point near
// the posed skin can be told where it would lie on the standing body. The fit's regions
// and girths are the standing body's (sim/fit/FitRegion.h); carried back to it, a sleeve on
// a raised arm is in the upper arms and a skirt over bent thighs in the thighs
// (docs/sizes.md, posed bodies).

#include <vector>

#include "sim/collision/TriangleBvh.h"
#include "sim/core/TriangleMesh.h"

namespace figment {

class PosedSkin {
 public:
  // Throws std::invalid_argument when the two differ in vertex count or triangles.
  PosedSkin(TriangleMesh rest, TriangleMesh posed);

  const TriangleMesh& rest() const { return rest_; }
  const TriangleMesh& posed() const { return posed_; }

  // `p` carried from the posed skin to the rest one: its closest point on the posed skin
  // goes to the same place (barycentric) on the same triangle at rest, and its offset from
  // there turns as that triangle's frame turned. Exact for a limb turned rigidly.
  Vec3 toRest(const Vec3& p) const { return carry(p, posedBvh_, posed_, rest_); }
  std::vector<Vec3> toRest(const std::vector<Vec3>& points) const;
  // The reverse: a point near the rest skin carried into the pose (a garment cut for the
  // standing body put on the posed one, for tests and pictures).
  Vec3 toPosed(const Vec3& p) const { return carry(p, restBvh_, rest_, posed_); }
  std::vector<Vec3> toPosed(const std::vector<Vec3>& points) const;

 private:
  static TriangleMesh matching(const TriangleMesh& rest, TriangleMesh posed);
  static Vec3 carry(const Vec3& p, const TriangleBvh& fromBvh, const TriangleMesh& from, const TriangleMesh& to);

  TriangleMesh rest_, posed_;
  TriangleBvh restBvh_, posedBvh_;
};

}  // namespace figment
