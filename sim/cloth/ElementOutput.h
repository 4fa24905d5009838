#pragma once
// What one element of the cloth model (a membrane section, a bending joint or section,
// the wind on a section) writes into its own slots (AssemblyPlan): its forces and, for a
// backward Euler step, its share of K v and of
//
//   A = mass M + damping C + stiffness K      (weights: 1, dt, dt^2 in a step)
//
// with K = -df/dx (projected to stay positive semi-definite) and C = -df/dv.

#include "sim/cloth/BlockSparseMatrix.h"

namespace figment {

struct SystemWeights {
  double mass = 1.0, damping = 0.0, stiffness = 0.0;
};

// Slots for an element of k nodes: force[a], stiffnessTimesVelocity[a] (K v at node a),
// blocks[a k + b] (damping C + stiffness K, weighted).
struct ElementOutput {
  Vec3* force;
  Vec3* stiffnessTimesVelocity;
  Block3* blocks;
};

}  // namespace figment
