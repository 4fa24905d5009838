#pragma once
// A sheet dropped on a ball: the implicit integrator's drape tests' scene (a 50 cm sheet
// of 16 x 16 quads let go 2 cm above a 15 cm ball).
#include <memory>

#include "sim/collision/MeshCollider.h"
#include "support/TestMeshes.h"

namespace figment::sheetonball {

inline constexpr double kRadius = 0.15;  // m, the ball

inline std::shared_ptr<const MeshCollider> ball() {
  return std::make_shared<MeshCollider>(meshes::sphere(kRadius, 48, 24));
}

inline TriangleMesh sheetAboveBall() {
  return meshes::grid(16, 16, 0.5, 0.5, Vec3(-0.25, kRadius + 0.02, 0.25), Vec3::UnitX(), -Vec3::UnitZ());
}

}  // namespace figment::sheetonball
