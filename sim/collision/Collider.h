#pragma once
// What cloth collides with (paper §3): anything that can tell whether a point has
// penetrated its surface (or come closer than a clearance), where the nearest surface
// point is, and the outward normal there.

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
};

}  // namespace figment
