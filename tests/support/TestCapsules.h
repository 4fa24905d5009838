#pragma once
// Capsules whose shape is known exactly, for collider and posing tests.

#include "sim/collision/Capsule.h"

namespace figment::test {

// A sphere-swept segment from a to b: hemispherical ends of `radius`.
inline CapsuleParameters segmentCapsule(const Vec3& a, const Vec3& b, double radius) {
  const Vec3 d = (b - a).normalized();
  CapsuleParameters c;
  c.x = c.z = 2.0 * radius;
  c.y = (b - a).norm() + 2.0 * radius;
  c.r1 = c.r2 = 2.0 * radius / c.y;
  c.tiltOnto(d);
  const Vec3 mid = 0.5 * (a + b);
  c.ox = mid.x(), c.oy = mid.y(), c.oz = mid.z();
  return c;
}

}  // namespace figment::test
