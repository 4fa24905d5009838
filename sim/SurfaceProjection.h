#pragma once
// The nearest point of a parametric surface W(t, a) to a point p, in world space:
// Levenberg-Marquardt on |W(t, a) - p|^2 over t in [tMin, tMax] and the angle a,
// from a starting (t, a) near the answer. Shared by the collision volumes (sim/Capsule.h,
// sim/RadialDepthVolume.h), whose scale, taper and varying radius move the nearest point
// away from a radial projection.

#include "TriangleMesh.h"

#include <functional>

namespace figment {

using SurfaceFunction = std::function<Vec3(double t, double a)>;

// Refines (t, a) in place; returns W(t, a).
Vec3 projectOntoSurface(const SurfaceFunction& surface, const Vec3& p, double tMin, double tMax, double& t, double& a);

// The unit outward normal at W(t, a) from its tangents, or `fallback` where they are
// parallel (a pole); `outwardHint` is any vector pointing out of the volume there.
Vec3 surfaceNormal(const SurfaceFunction& surface, double tMin, double tMax, double t, double a,
                   const Vec3& outwardHint, const Vec3& fallback);

}  // namespace figment
