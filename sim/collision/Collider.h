#pragma once
// What cloth collides with (paper §3): anything that can tell whether a point has
// penetrated its surface (or come closer than a clearance), where the nearest surface
// point is, and the outward normal there.

#include <Eigen/Geometry>
#include <memory>

#include "sim/core/TriangleMesh.h"

namespace figment {

struct Contact {
  Vec3 surfacePoint;  // nearest point on the collider's surface, m
  Vec3 normal;        // unit outward normal at surfacePoint
  double distance;    // signed distance of the query point, m (negative = inside)
};

class Collider {
 public:
  virtual ~Collider() = default;
  // True when `p` is inside or within `clearance` of the surface; `searchRadius` bounds
  // how far from the surface the query looks (a point inside is found when it lies
  // within `searchRadius` of the surface). When it returns false, out.distance is a lower
  // bound of p's distance to the surface: the distance found, or searchRadius when
  // nothing lies within it; a caller may skip queries while p has not moved that far.
  virtual bool contact(const Vec3& p, double clearance, double searchRadius, Contact& out) const = 0;

  // The broad phase (BroadPhaseCollider): this collider without its parts that lie at
  // least `reach` from every point of `region`, or null when it would leave none out (or
  // has no parts to leave). For p in `region` the focused collider answers as this one,
  // except that (a) where nothing touches p its lower bound counts only the parts kept (the
  // distance to this collider is at least min(that bound, reach)), and (b) a push-out
  // target more than reach - clearance from p was not checked against the parts left out.
  virtual std::shared_ptr<const Collider> focusedOn(const Eigen::AlignedBox3d& region, double reach) const;

  // A body that moves during the drape (MovingMeshCollider: a posed body turning into its
  // pose) follows the drape's clock (DrapeRequest::bodyClock) through these, wherever it
  // sits: alone, or a part of a CompositeCollider (a CollisionGroup's). A still collider
  // does not move and ignores the clock.
  virtual bool moves() const { return false; }
  // Moves it to its shape at simulated time `time` (s). Not concurrent with contact().
  virtual void advanceTo(double /*time*/) const {}
};

}  // namespace figment
