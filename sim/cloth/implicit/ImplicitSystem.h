#pragma once
// The garment's forces and their derivatives at one state, assembled for a backward
// Euler step (sim/cloth/implicit/ImplicitEuler.h): the same physical model as
// sim/cloth/ClothModel.h (membrane with strain-rate damping, plate bending, gravity,
// air resistance, wind), without its explicit stability measures (strain clamping,
// acceleration limiting).
//
//   forces()                  f(x, v, t) per node, N
//   stiffnessTimesVelocity()  K v per node, N/s (K = -df/dx, projected:
//                             sim/cloth/MembraneElement.h, PlateBending.h)
//   matrix()                  A = mass M + damping C + stiffness K, C = -df/dv (strain-rate
//                             damping and air resistance); the wind's derivative is left out
//
// Parallel (OpenMP, OMP_NUM_THREADS threads): every element's terms are computed into
// its own slots, then summed per node in a fixed order (AssemblyPlan.h): the result
// does not depend on the thread count.

#include "sim/cloth/ClothModel.h"
#include "sim/cloth/implicit/AssemblyPlan.h"

#include <vector>

namespace figment {

class ImplicitSystem {
 public:
  // `model` (kept by reference) gives the sections, bending forms, held nodes and masses.
  ImplicitSystem(const ClothModel& model, const ClothParameters& parameters);

  void assemble(const std::vector<Vec3>& x, const std::vector<Vec3>& v, double t, const SystemWeights& weights);

  const std::vector<Vec3>& forces() const { return force_; }
  const std::vector<Vec3>& stiffnessTimesVelocity() const { return stiffnessVelocity_; }
  const BlockSparseMatrix& matrix() const { return matrix_; }
  // Penalty contacts add their terms to the diagonal blocks after assembly.
  BlockSparseMatrix& matrix() { return matrix_; }
  const std::vector<double>& masses() const { return model_.masses(); }  // kg
  const ClothModel& model() const { return model_; }

 private:
  void computeElements(const std::vector<Vec3>& x, const std::vector<Vec3>& v, double t,
                       const SystemWeights& weights);
  void computeBending(const std::vector<Vec3>& v, const SystemWeights& weights);
  ElementOutput slots(int element);

  const ClothModel& model_;
  ClothParameters parameters_;
  // Elements: the membrane sections, the bending sections (with the `sections` form of
  // the bending stiffness: they carry its blocks), the joints (the bending forces and, in
  // the `joints` form, the blocks).
  AssemblyPlan plan_;
  int jointElements_ = 0;  // the first joint's element
  std::vector<JointAngle> angles_;
  bool jointBound_ = false;
  std::vector<Eigen::Vector3d> moments_;
  std::vector<Vec3> forceSlots_, stiffnessVelocitySlots_;
  std::vector<Block3> blockSlots_;
  std::vector<double> diagonal_;
  std::vector<Vec3> force_, stiffnessVelocity_;
  BlockSparseMatrix matrix_;
};

}  // namespace figment
