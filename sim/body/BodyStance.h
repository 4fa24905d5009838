#pragma once
// How a body mesh stands: the axis direction its feet are below and its head above, and
// its stature along it. The skeleton estimate turns any standing humanoid upright with it
// (sim/body/SkeletonEstimate.h); the tools check with it that a body is already upright
// and human-sized in metres before fitting volumes or cutting a garment round it, whose
// thresholds are in metres (a 2 cm section spacing, an 8 mm capsule gap, a 1 cm
// clearance, a 4 cm gap between limbs).

#include <optional>

#include "sim/core/TriangleMesh.h"

namespace figment {

// The statures (m) the metric thresholds above hold for: a child of about 4 years to a
// tall adult. A body outside them is in another unit (or not a human).
constexpr double kMinStature = 0.8;
constexpr double kMaxStature = 2.5;

// Of the six axis directions spanning at least 80 % of the largest extent, the first
// (+x, -x, +y, -y, +z, -z) whose lowest slab (4 % of the extent) holds two separate
// clusters of vertices (the feet) and whose highest slab holds one (the head); nullopt
// when none does (not a standing humanoid: legs together, lying down, no legs).
std::optional<Vec3> standingUpDirection(const std::vector<Vec3>& vertices);

struct BodyStance {
  std::optional<Vec3> up;  // standingUpDirection
  double stature = 0;      // the extent along `up` (along +y when there is none), in the mesh's unit
};

// Throws std::invalid_argument for a mesh without vertices.
BodyStance measureStance(const TriangleMesh& body);

}  // namespace figment
