#include "sim/cloth/PlaneStressLaw.h"

namespace figment {

PlaneStressLaw::PlaneStressLaw(const Material& material)
    : poissonRatio_(material.poissonRatio),
      stretch_(material.youngsModulus / (1.0 - material.poissonRatio * material.poissonRatio)),
      shear_(material.youngsModulus / (1.0 + material.poissonRatio)),
      thickness_(material.thickness) {
  const double k = stretch_, nu = poissonRatio_;
  tangent_ << k, k * nu, 0.0, k * nu, k, 0.0, 0.0, 0.0, 2.0 * shear_;
}

PlaneStress PlaneStressLaw::stress(const Eigen::Vector3d& e) const {
  const double nu = poissonRatio_;
  return {stretch_ * (e[0] + nu * e[1]), stretch_ * (e[1] + nu * e[0]), shear_ * e[2]};
}

double PlaneStressLaw::energyDensity(const Eigen::Vector3d& e) const {
  const PlaneStress s = stress(e);
  return 0.5 * (s.sigmaU * e[0] + s.sigmaV * e[1]) + s.tauUV * e[2];
}

}  // namespace figment
