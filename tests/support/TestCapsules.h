#pragma once
// Capsules whose shape is known exactly, for collider and posing tests.

#include "sim/collision/Capsule.h"

#include <algorithm>
#include <cmath>

namespace figment::test {

// A sphere-swept segment from a to b: hemispherical ends of `radius`.
inline CapsuleParameters segmentCapsule(const Vec3& a, const Vec3& b, double radius) {
  const Vec3 d = (b - a).normalized();
  CapsuleParameters c;
  c.x = c.z = 2.0 * radius;
  c.y = (b - a).norm() + 2.0 * radius;
  c.r1 = c.r2 = 2.0 * radius / c.y;
  // The tilt about (cos phi, 0, sin phi) by theta takes y to (-sin phi sin theta, cos theta, cos phi sin theta).
  c.theta = std::acos(std::clamp(d.y(), -1.0, 1.0));
  c.phi = std::sin(c.theta) > 1e-12 ? std::atan2(-d.x(), d.z()) : 0.0;
  const Vec3 mid = 0.5 * (a + b);
  c.ox = mid.x(), c.oy = mid.y(), c.oz = mid.z();
  return c;
}

}  // namespace figment::test
