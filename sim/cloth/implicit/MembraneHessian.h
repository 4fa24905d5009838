#pragma once
// A membrane section's force and its derivatives for the implicit integrator: the same
// constant-strain St. Venant-Kirchhoff section as sim/cloth/MembraneElement.h (without
// strain clamping, an explicit stability measure).
//
// With F = sum_a x_a beta_a^T (beta from Dm^-1), Green strain e = (E_uu, E_vv, E_uv),
// e' = sum_a B_a v_a its rate, C the plane-stress law's tangent (PlaneStressLaw.h) and
// V = A h:
//   force     f_a  = -V B_a^T C (e + tau e')                      (= -V F S beta_a)
//   stiffness K_ab =  V B_a^T C B_b  +  V (beta_a^T S+ beta_b) I3
//   damping   C_ab =  tau V B_a^T C B_b                          (strain-rate damping)
// B_a: rows beta_a0 f0^T, beta_a1 f1^T, (beta_a0 f1 + beta_a1 f0)^T / 2 (f: columns of F).
//
// Projection: the first term of K is positive semi-definite for any state (a Gram form
// of C); the second, the geometric stiffness, is indefinite where the section is
// compressed (S has a negative eigenvalue) and makes the system matrix indefinite under
// compression, which wrinkling cloth always is somewhere. S+ keeps S's non-negative
// eigenvalues only (a closed-form 2x2 clamp): K is then positive semi-definite, exact
// where the section is stretched in both directions, and far cheaper than clamping the
// 9x9 eigenvalues per section. The damping force's dependence on x is left out (it
// vanishes at rest), as in Baraff & Witkin 1998.

#include "sim/cloth/MembraneElement.h"
#include "sim/cloth/implicit/ElementOutput.h"

namespace figment {

// Writes the section's 3 forces, K v and 9 weighted blocks (corner order) into `out`.
void membraneContribution(const MembraneElement& section, const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                          const PlaneStressLaw& law, double tauDamping, const SystemWeights& weights,
                          const ElementOutput& out);

// S with its negative eigenvalues set to zero.
Eigen::Matrix2d positivePart(const Eigen::Matrix2d& S);

}  // namespace figment
