#pragma once
// One triangular cloth section (paper §2, Fig. 2.1): in-plane stretch (sigma_u, sigma_v)
// and shear (tau_uv) from the section's distortion against its unstressed shape.
//
// Based on: the constant-strain triangle with St. Venant-Kirchhoff plane stress
// (e.g. Volino, Magnenat-Thalmann & Faure, "A simple approach to nonlinear tensile
// stiffness for accurate cloth simulation", ACM TOG 2009), which keeps the paper's
// material parameters (E, nu, h) and its stress components (sim/cloth/PlaneStressLaw.h).
//
//   rest frame (u, v) in the section's plane;  Dm = [X1-X0, X2-X0] in (u, v)  (2x2)
//   F   = [x1-x0, x2-x0] Dm^-1                 deformation gradient (3x2)
//   eps = (F^T F - I) / 2                       Green strain: eps_uu, eps_vv, eps_uv
//   sigma_u, sigma_v, tau_uv = the law's stress of eps
//   forces on corners 1, 2: -A h F S Dm^-T, corner 0: minus their sum (N)
// A strain-rate term eps' * tauDamping (Kelvin-Voigt) is added to eps in the stress;
// it damps the fast in-plane modes an explicit integrator cannot resolve and vanishes
// at rest, so it does not change the draped shape.

#include "sim/cloth/PlaneStressLaw.h"
#include "sim/core/TriangleMesh.h"

#include <Eigen/Core>

namespace figment {

class MembraneElement {
 public:
  // Rest corners X0, X1, X2 (m). Returns false through `valid()` for a degenerate section.
  MembraneElement(const Triangle& corners, const Vec3& X0, const Vec3& X1, const Vec3& X2);

  bool valid() const { return restArea_ > 0.0; }
  const Triangle& corners() const { return corners_; }
  double restArea() const { return restArea_; }  // m^2
  const Eigen::Matrix2d& restInverse() const { return restInverse_; }  // Dm^-1, 1/m

  // Green strain (eps_uu, eps_vv, eps_uv) of the section at positions x.
  Eigen::Vector3d strain(const std::vector<Vec3>& x) const;

  // Elastic energy A h w(eps) (J, w the law's energy density); its negative gradient is
  // the force.
  double energy(const std::vector<Vec3>& x, const PlaneStressLaw& law) const;

  // Adds the elastic (and strain-rate damping) forces of this section to `force`. With
  // strainLimit > 0 each strain component is first clamped into [-limit, limit] (the
  // paper's strain clamping: a section distorted beyond a realistic range pulls no
  // harder than at the range's edge). Returns whether the clamp changed a strain.
  bool addForces(const std::vector<Vec3>& x, const std::vector<Vec3>& v, const PlaneStressLaw& law,
                 double tauDamping, double strainLimit, std::vector<Vec3>& force) const;
  // Adds the strain-rate damping forces alone (addForces with tauDamping adds them too):
  // for an acceleration limiter that must cut the elastic pull, never the damping.
  void addDampingForces(const std::vector<Vec3>& x, const std::vector<Vec3>& v, const PlaneStressLaw& law,
                        double tauDamping, std::vector<Vec3>& force) const;

 private:
  // Adds the forces of the stress that strain `e` gives, at deformation gradient F.
  void addStressForces(const Eigen::Matrix<double, 3, 2>& F, const Eigen::Vector3d& e, const PlaneStressLaw& law,
                       std::vector<Vec3>& force) const;

  Triangle corners_;
  Eigen::Matrix2d restInverse_;  // Dm^-1
  double restArea_ = 0.0;
};

}  // namespace figment
