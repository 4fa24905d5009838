#pragma once
// A T-posed humanoid skeleton with round numbers, for tests of sim/body: y up, facing +z,
// left = +x; waist joint at y = 1.1, chest joint at 1.3 (hips 0.9-1.1, lower torso
// 1.1-1.3, upper torso 1.3-1.5), arms along x at 1.45 m.

#include <string>

#include "sim/body/Skeleton.h"

namespace figment::test {

inline Skeleton roundNumberTPose() {
  return humanoidSkeleton({{0, 1.0, 0},     {0, 1.1, 0},      {0, 1.3, 0},      {0, 1.5, 0},
                           {0, 1.6, 0},     {0, 1.8, 0},                                            // spine
                           {0.1, 0.95, 0},  {0.1, 0.5, 0},    {0.1, 0.08, 0},   {0.1, 0.0, 0.15},   // left leg
                           {-0.1, 0.95, 0}, {-0.1, 0.5, 0},   {-0.1, 0.08, 0},  {-0.1, 0.0, 0.15},  // right leg
                           {0.2, 1.45, 0},  {0.5, 1.45, 0},   {0.75, 1.45, 0},  {0.95, 1.45, 0},    // left arm
                           {-0.2, 1.45, 0}, {-0.5, 1.45, 0},  {-0.75, 1.45, 0}, {-0.95, 1.45, 0},   // right arm
                           {0.05, 1.45, 0}, {-0.05, 1.45, 0}, {0, 0.9, 0}});  // shoulder bases, pelvis floor
}

// The index of the part named `name`, or -1.
inline int partIndex(const Skeleton& s, const std::string& name) {
  for (size_t k = 0; k < s.parts.size(); ++k)
    if (s.parts[k].name == name) return static_cast<int>(k);
  return -1;
}

}  // namespace figment::test
