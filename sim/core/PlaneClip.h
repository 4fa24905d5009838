#pragma once
// Cutting a mesh along a plane: what lies on the plane's front (normal) side stays,
// triangles across it are cut where their edges cross it, so the new boundary runs
// straight along the plane (a garment's hem cut level, not along the body's triangles).

#include "sim/core/TriangleMesh.h"

namespace figment {

struct Plane {
  Vec3 point, normal;  // normal: unit, towards the side that is kept
  double signedDistance(const Vec3& x) const { return (x - point).dot(normal); }
};

// The part of `mesh` in front of `plane`. Vertices within `snap` of the plane are moved
// onto it first (along the normal), so no cut leaves a sliver thinner than `snap`.
// Windings are kept; new vertices (one per cut edge) follow the old ones; unused
// vertices are dropped (numbered as the triangles first use them).
TriangleMesh clippedByPlane(const TriangleMesh& mesh, const Plane& plane, double snap = 0.0);

}  // namespace figment
