#pragma once
// The cloth sheet's plane-stress law (paper §2: stretch sigma_u, sigma_v and shear
// tau_uv from the material's E, nu and h), St. Venant-Kirchhoff in the section's Green
// strain e = (eps_uu, eps_vv, eps_uv), written once for every integrator:
//
//   sigma_u = E/(1-nu^2) (eps_uu + nu eps_vv)   sigma_v = E/(1-nu^2) (eps_vv + nu eps_uu)
//   tau_uv  = E/(1+nu) eps_uv                    (= 2 G eps_uv)                        Pa
//   w(e)    = (sigma_u eps_uu + sigma_v eps_vv) / 2 + tau_uv eps_uv                 J/m^3
//   dw/de   = (sigma_u, sigma_v, 2 tau_uv)       (eps_uv stands for eps_uv and eps_vu)
//   C       = d^2 w / de^2 = [k, k nu, 0; k nu, k, 0; 0, 0, 2E/(1+nu)],  k = E/(1-nu^2)
//
// The stress is linear in the strain, so C is constant: the membrane's stiffness
// (MembraneElement.h) is B^T C B with B = de/dx.

#include <Eigen/Core>

#include "sim/cloth/Material.h"

namespace figment {

struct PlaneStress {
  double sigmaU, sigmaV, tauUV;  // Pa
};

class PlaneStressLaw {
 public:
  explicit PlaneStressLaw(const Material& material);

  PlaneStress stress(const Eigen::Vector3d& strain) const;
  double energyDensity(const Eigen::Vector3d& strain) const;   // J/m^3
  const Eigen::Matrix3d& tangent() const { return tangent_; }  // C, Pa
  double thickness() const { return thickness_; }              // h, m: a section's volume is A h

 private:
  double poissonRatio_, stretch_, shear_;  // nu; k = E/(1-nu^2); E/(1+nu), Pa
  double thickness_;
  Eigen::Matrix3d tangent_;
};

}  // namespace figment
