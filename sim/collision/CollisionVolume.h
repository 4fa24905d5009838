#pragma once
// One body part's collision volume (paper §3), whatever its kind, in the part's rest
// frame, and the same volume carried into the posed world by an affine map (paper §3.3:
// "the application of geometric transformations to animate the mannequin and to adjust
// its dimensions and proportions").
//
// Under a map x -> A x + b (A invertible):
//   inside        exact for any A: the rest volume contains A^-1 (x - b);
//   similar A     (a rotation times a uniform scale s: posing, height) the rest-frame
//                 nearest point and normal, mapped, the distance times s: exact;
//   other A       (girth and arm length stretches) the nearest point of the mapped surface is not the
//                 image of the rest-frame one: a parametric volume corrects it on the
//                 mapped surface W(t, a) = A S(t, a) + b (Gauss-Newton from the rest
//                 frame's start, Levenberg-Marquardt where that stops short, as near a
//                 capsule's pole; tangents A dS/dt, A dS/da, normal their cross product);
//                 a triangle mesh is rebuilt from its mapped triangles (exact).

#include <Eigen/Geometry>
#include <algorithm>
#include <memory>

#include "sim/collision/Capsule.h"      // SurfacePoint
#include "sim/collision/RadialDepth.h"  // RadialDepthParameters
#include "sim/core/TriangleMesh.h"

namespace figment {

// The points within `radius` (m) of the segment a-b.
struct BoundingCapsule {
  Vec3 a, b;
  double radius = 0.0;
  // p's signed distance to this capsule: a lower bound of its signed distance to anything
  // inside it.
  double gap(const Vec3& p) const {
    const Vec3 ab = b - a, ap = p - a;
    const double length2 = ab.squaredNorm();
    const double t = length2 > 0.0 ? std::clamp(ap.dot(ab) / length2, 0.0, 1.0) : 0.0;
    return (ap - t * ab).norm() - radius;
  }
};

class CollisionVolume {
 public:
  virtual ~CollisionVolume() = default;
  virtual bool contains(const Vec3& p) const = 0;
  // The nearest surface point, the outward normal there and p's signed distance (< 0
  // inside); the volume's fast path where it has one.
  virtual SurfacePoint nearest(const Vec3& p) const = 0;
  // A sphere enclosing the volume, for early-outs: centre (m) and radius (m).
  virtual Vec3 centre() const = 0;
  virtual double boundingRadius() const = 0;
  // A capsule enclosing the volume (the points within `radius` of the segment a-b), a
  // tighter early-out for long parts; the default is the bounding sphere.
  virtual BoundingCapsule boundingCapsule() const { return {centre(), centre(), boundingRadius()}; }
  // A lower bound of p's signed distance (m) without a nearest-point search: where it is
  // at least the clearance, so is the distance. Any enclosing set's signed distance is
  // one (a point inside is no deeper than the way out of the enclosing set); the
  // default is the bounding capsule's, a radial volume's is tighter
  // (RadialDepth::distanceBound).
  virtual double distanceBound(const Vec3& p) const { return boundingCapsule().gap(p); }

  // The nearest point to world point p of this volume's image under `map` (`inverse` its
  // inverse), for a map that is not a similarity. The default maps the rest-frame answer
  // (normal by A^-T): approximate; parametric volumes override it with the correction above.
  virtual SurfacePoint nearestUnder(const Eigen::Affine3d& map, const Eigen::Affine3d& inverse, const Vec3& p) const;
  // This volume with `map` built in, where it can carry any affine map exactly (a mesh:
  // its mapped triangles); null otherwise.
  virtual std::shared_ptr<const CollisionVolume> mappedCopy(const Eigen::Affine3d& map) const;
};

std::shared_ptr<const CollisionVolume> makeVolume(const CapsuleParameters& parameters);      // Capsule::nearestFast
std::shared_ptr<const CollisionVolume> makeVolume(const RadialDepthParameters& parameters);  // ...::nearestFast
// Exact: a bounding-volume hierarchy over a part's own triangles, closed or not; inside =
// behind the nearest feature's angle-weighted pseudo-normal, as MeshCollider decides,
// but never where that feature is on an open edge (the cut to a neighbouring part, whose
// own volume answers there: OpenEdges::Outside).
// Throws std::invalid_argument when it has no triangles.
std::shared_ptr<const CollisionVolume> makeVolume(TriangleMesh partTriangles);

// `volume` carried by `transform` (its rest frame -> world), answering in world space.
// Throws std::invalid_argument when `volume` is null or `transform` is singular.
std::shared_ptr<const CollisionVolume> transformedVolume(std::shared_ptr<const CollisionVolume> volume,
                                                         const Eigen::Affine3d& transform);

}  // namespace figment
