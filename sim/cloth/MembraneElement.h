#pragma once
// One triangular cloth section (paper §2, Fig. 2.1): in-plane stretch (sigma_u, sigma_v)
// and shear (tau_uv) from the section's distortion against its unstressed shape; its
// force and, when an implicit step asks, its stiffness and damping, from one derivation.
//
// Based on: the constant-strain triangle with St. Venant-Kirchhoff plane stress
// (e.g. Volino, Magnenat-Thalmann & Faure, "A simple approach to nonlinear tensile
// stiffness for accurate cloth simulation", ACM TOG 2009), which keeps the paper's
// material parameters (E, nu, h) and its stress components (PlaneStressLaw.h); the
// force with its derivatives as ARCSim's stretching_force (Narain, Samii & O'Brien,
// "Adaptive anisotropic remeshing for cloth simulation", SIGGRAPH Asia 2012).
//
//   rest frame (u, v) in the section's plane;  Dm = [X1-X0, X2-X0] in (u, v)  (2x2)
//   F   = [x1-x0, x2-x0] Dm^-1 = sum_a x_a beta_a^T   deformation gradient (3x2);
//         beta_1, beta_2 the rows of Dm^-1, beta_0 = -(beta_1 + beta_2)
//   e   = (F^T F - I) / 2                  Green strain (eps_uu, eps_vv, eps_uv)
//   e'  = (F'^T F + F^T F') / 2 = sum_a B_a v_a   its rate;  B_a = de/dx_a, rows
//         beta_a0 f0^T, beta_a1 f1^T, (beta_a0 f1 + beta_a1 f0)^T / 2 (f: columns of F)
//   W   = V w(e),  V = A h                 energy (J), w the law's energy density
//   f_a = -V F S beta_a,  S = stress(e + tau e')   force (N): corners 1, 2 the columns
//         of -V F S Dm^-T, corner 0 minus their sum
//   K_ab = -df_a/dx_b = V B_a^T C B_b + V (beta_a^T S+ beta_b) I3       stiffness (N/m)
//   D_ab = -df_a/dv_b = tau V B_a^T C B_b                               damping (N s/m)
//
// The strain-rate term tau e' (Kelvin-Voigt) damps the fast in-plane modes and
// vanishes at rest, so it does not change the draped shape; its dependence on x is
// left out of K (it vanishes at rest), as in Baraff & Witkin 1998.
//
// Projection: V B^T C B is positive semi-definite for any state (a Gram form of C); the
// geometric stiffness V beta^T S beta I is indefinite where the section is compressed (S
// has a negative eigenvalue), which wrinkling cloth always is somewhere. S+ keeps S's
// non-negative eigenvalues only (a closed-form 2x2 clamp; S the elastic stress, without
// the damping's): K is then positive semi-definite, exact where the section is stretched
// in both directions, and far cheaper than clamping the 9x9 eigenvalues per section.
//
// The explicit integrators' strain clamping (the paper's: a section distorted beyond a
// realistic range pulls no harder than at the range's edge) clamps e before the damping
// is added; K and D describe the unclamped force.

#include <Eigen/Core>
#include <array>

#include "sim/cloth/ElementOutput.h"
#include "sim/cloth/PlaneStressLaw.h"
#include "sim/core/TriangleMesh.h"

namespace figment {

// What an evaluation asks of a section.
struct MembraneRequest {
  bool elastic = true;       // the stress of the strain e
  double damping = 0.0;      // tau, s: the stress of tau e' (0: none)
  double strainLimit = 0.0;  // > 0: each strain component clamped into [-limit, limit] first
};

class MembraneElement {
 public:
  // Rest corners X0, X1, X2 (m). Returns false through `valid()` for a degenerate section.
  MembraneElement(const Triangle& corners, const Vec3& X0, const Vec3& X1, const Vec3& X2);

  bool valid() const { return restArea_ > 0.0; }
  const Triangle& corners() const { return corners_; }
  double restArea() const { return restArea_; }                        // m^2
  const Eigen::Matrix2d& restInverse() const { return restInverse_; }  // Dm^-1, 1/m

  // Green strain (eps_uu, eps_vv, eps_uv) of the section at positions x.
  Eigen::Vector3d strain(const std::vector<Vec3>& x) const;
  // W at positions x (J); its negative gradient is the elastic force.
  double energy(const std::vector<Vec3>& x, const PlaneStressLaw& law) const;

  // Writes the forces f_a at (x, v) into out.force[a] (corner order); with `weights`,
  // also K v into out.stiffnessTimesVelocity[a] and the blocks damping D + stiffness K,
  // weighted, into out.blocks[3 a + b]. Returns whether the strain clamp changed a strain.
  bool evaluate(const std::vector<Vec3>& x, const std::vector<Vec3>& v, const PlaneStressLaw& law,
                const MembraneRequest& request, const SystemWeights* weights, const ElementOutput& out) const;

 private:
  void writeDerivatives(const Eigen::Matrix<double, 3, 2>& F, const Eigen::Vector3d& strain, const std::vector<Vec3>& v,
                        const PlaneStressLaw& law, double tauDamping, const SystemWeights& weights,
                        const ElementOutput& out) const;

  Triangle corners_;
  Eigen::Matrix2d restInverse_;  // Dm^-1
  double restArea_ = 0.0;
};

// S with its negative eigenvalues set to zero.
Eigen::Matrix2d positivePart(const Eigen::Matrix2d& S);

}  // namespace figment
