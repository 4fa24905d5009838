#pragma once
// A two-bone arm along +x for the skeleton's tests: shoulder (origin) -> elbow (1 m) -> wrist
// (2 m), the parts upperArm (0 -> 1) and forearm (1 -> 2).

#include "sim/body/Skeleton.h"

namespace figment::test {

inline Skeleton armSkeleton() {
  Skeleton s;
  s.joints = {{"shoulder", -1, Vec3(0, 0, 0)}, {"elbow", 0, Vec3(1, 0, 0)}, {"wrist", 1, Vec3(2, 0, 0)}};
  s.parts = {{"upperArm", 0, 1}, {"forearm", 1, 2}};
  return s;
}

}  // namespace figment::test
