#pragma once
// The exact collider (paper §3's reference): the body's own closed triangle surface,
// queried through a bounding-volume hierarchy. Inside/outside from the angle-weighted
// pseudo-normal at the closest feature (Baerentzen & Aanaes 2005).

#include "sim/collision/Collider.h"
#include "sim/collision/TriangleBvh.h"

namespace figment {

// What a point whose closest feature is an open edge (one triangle only) or a vertex on
// one is: decided by the pseudo-normal there as anywhere else (a closed surface has
// none), or outside. A part of a body cut from the rest (an exact part) is open at the
// cut, where the pseudo-normal says nothing about the body beyond; there the neighbouring
// part's collider answers.
enum class OpenEdges { PseudoNormal, Outside };

class MeshCollider : public Collider {
 public:
  // `surface` should be closed (or open only where `openEdges` says so) and consistently
  // wound (counter-clockwise from outside).
  explicit MeshCollider(TriangleMesh surface, OpenEdges openEdges = OpenEdges::PseudoNormal);
  // `shape`'s surface with its vertices moved to `vertices` (the same triangles, the same
  // open edges): a moving body's next keyframe without numbering its edges again, a third
  // of the cost. Throws std::invalid_argument when the vertex count differs.
  MeshCollider(const MeshCollider& shape, std::vector<Vec3> vertices);
  bool contact(const Vec3& p, double clearance, double searchRadius, Contact& out) const override;
  const TriangleMesh& surface() const { return surface_; }
  const TriangleBvh& bvh() const { return bvh_; }

 private:
  TriangleMesh surface_;
  TriangleBvh bvh_;
  std::vector<Vec3> faceNormals_, vertexNormals_;
  std::vector<Vec3> edgeNormals_;  // per triangle edge (3 per triangle), angle-weighted sum
  std::vector<int> edgeOf_;        // per triangle edge, its edge's number
  int edgeCount_ = 0;
  // With OpenEdges::Outside: per triangle edge and per vertex, whether it is (on) an open edge.
  std::vector<char> openEdge_, openVertex_;
  bool onOpenEdge(const ClosestPoint& closest) const;
  void computeNormals();
};

}  // namespace figment
