#pragma once
// What a solve may change at each node (Baraff & Witkin 1998, section 5.3): the filter
// S_i projects onto the directions node i is free to move in: I (free), I - n n^T (held
// on a surface of normal n), 0 (fixed); the constrained part of its answer is prescribed.

#include <vector>

#include "sim/core/TriangleMesh.h"

namespace figment {

struct NodeFilter {
  enum Kind : char { Free, Sliding, Fixed };
  std::vector<char> kind;        // per node
  std::vector<Vec3> normal;      // per node, unit: the constrained direction of a Sliding node
  std::vector<Vec3> prescribed;  // z per node: Sliding along normal, Fixed any; Free zero

  void reset(size_t nodes);
  Vec3 apply(int i, const Vec3& v) const {
    switch (kind[i]) {
      case Free:
        return v;
      case Sliding:
        return v - normal[i].dot(v) * normal[i];
      default:
        return Vec3::Zero();
    }
  }
};

}  // namespace figment
