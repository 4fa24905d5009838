#pragma once
// The exact collider (paper §3's reference): the body's own closed triangle surface,
// queried through a bounding-volume hierarchy. Inside/outside from the angle-weighted
// pseudo-normal at the closest feature (Baerentzen & Aanaes 2005).

#include "sim/collision/Collider.h"
#include "sim/collision/TriangleBvh.h"

namespace figment {

class MeshCollider : public Collider {
 public:
  // `surface` should be closed and consistently wound (counter-clockwise from outside).
  explicit MeshCollider(TriangleMesh surface);
  bool contact(const Vec3& p, double clearance, double searchRadius, Contact& out) const override;
  const TriangleMesh& surface() const { return surface_; }
  const TriangleBvh& bvh() const { return bvh_; }

 private:
  TriangleMesh surface_;
  TriangleBvh bvh_;
  std::vector<Vec3> faceNormals_, vertexNormals_;
  std::vector<Vec3> edgeNormals_;  // per triangle edge (3 per triangle), angle-weighted sum
};

}  // namespace figment
