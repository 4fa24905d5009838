#pragma once
// Cutting a mesh along a plane: what lies on the plane's front (normal) side stays,
// triangles across it are cut where their edges cross it, so the new boundary runs
// straight along the plane (a garment's hem cut level, not along the body's triangles).

#include <variant>
#include <vector>

#include "sim/core/TriangleMesh.h"

namespace figment {

struct Plane {
  Vec3 point, normal;  // normal: unit, towards the side that is kept
  double signedDistance(const Vec3& x) const { return (x - point).dot(normal); }
  Vec3 projected(const Vec3& x) const { return x - signedDistance(x) * normal; }
};

// A sphere to cut along, keeping what lies outside it: a neckline round the neck's base
// (a plane there would graze the shoulders' tops, where its trace turns sharply).
struct Sphere {
  Vec3 centre;
  double radius = 0;
  double signedDistance(const Vec3& x) const { return (x - centre).norm() - radius; }
  Vec3 projected(const Vec3& x) const { return centre + radius * (x - centre).normalized(); }
};

using CutSurface = std::variant<Plane, Sphere>;
double signedDistance(const CutSurface& surface, const Vec3& x);
Vec3 projected(const CutSurface& surface, const Vec3& x);  // the nearest point on it

// The part of `mesh` in front of `plane`. Vertices within `snap` of the plane are moved
// onto it first (along the normal), so no cut leaves a sliver thinner than `snap`.
// Windings are kept; new vertices (one per cut edge) follow the old ones; unused
// vertices are dropped (numbered as the triangles first use them).
TriangleMesh clippedByPlane(const TriangleMesh& mesh, const Plane& plane, double snap = 0.0);

// Each vertex cut by its own surface: surfaces[surfaceOf[v]], or none where
// surfaceOf[v] < 0 (kept). A triangle is cut only where its corners share one surface; the
// others are kept whole, and only vertices with a surface are snapped (along its normal).
// Two sleeves' ends, each cut across its own arm's axis, whose plane would also cut through
// the torso beside it. Each surface's cut must lie inside its vertices' region, clear of its
// border (no triangle it crosses beside one with another surface or none), or its edge
// meets the triangles kept whole at T-junctions.
TriangleMesh clippedBySurfaces(const TriangleMesh& mesh, const std::vector<CutSurface>& surfaces,
                               const std::vector<int>& surfaceOf, double snap = 0.0);

}  // namespace figment
