// The plane-stress law's stress is the gradient of its energy density (with the shear
// strain counted twice), and its tangent C is the stress's derivative.
#include <gtest/gtest.h>

#include "sim/cloth/PlaneStressLaw.h"

using namespace figment;

namespace {
Material cotton() {
  return Material{0.0005, 300.0, 2.0e6, 0.3};
}

// dw/de = (sigma_u, sigma_v, 2 tau_uv): the energy-conjugate stress.
Eigen::Vector3d conjugate(const PlaneStress& s) {
  return {s.sigmaU, s.sigmaV, 2.0 * s.tauUV};
}
}  // namespace

TEST(PlaneStressLaw, StressIsTheEnergyDensityGradient) {
  const PlaneStressLaw law(cotton());
  const Eigen::Vector3d e(0.02, -0.01, 0.015);
  const double h = 1e-7;
  const Eigen::Vector3d stress = conjugate(law.stress(e));
  for (int k = 0; k < 3; ++k) {
    Eigen::Vector3d plus = e, minus = e;
    plus[k] += h;
    minus[k] -= h;
    const double numerical = (law.energyDensity(plus) - law.energyDensity(minus)) / (2 * h);
    EXPECT_NEAR(stress[k], numerical, 1e-6 * stress.norm()) << "component " << k;
  }
}

TEST(PlaneStressLaw, TangentIsTheStressDerivative) {
  const PlaneStressLaw law(cotton());
  const Eigen::Vector3d e(0.02, -0.01, 0.015);
  for (int k = 0; k < 3; ++k) {
    Eigen::Vector3d plus = e, minus = e;
    plus[k] += 1e-6;
    minus[k] -= 1e-6;
    const Eigen::Vector3d column = (conjugate(law.stress(plus)) - conjugate(law.stress(minus))) / 2e-6;
    EXPECT_LT((law.tangent().col(k) - column).norm(), 1e-6 * law.tangent().norm()) << "component " << k;
  }
  EXPECT_EQ(law.tangent(), law.tangent().transpose());
}

TEST(PlaneStressLaw, ShearIsTwiceTheShearModulusTimesTheStrain) {
  const PlaneStressLaw law(cotton());
  const double G = 2.0e6 / (2 * 1.3);
  EXPECT_NEAR(law.stress({0.0, 0.0, 0.01}).tauUV, 2 * G * 0.01, 1e-6);
  EXPECT_NEAR(law.energyDensity({0.0, 0.0, 0.01}), 2 * G * 0.01 * 0.01, 1e-9);
  EXPECT_EQ(law.thickness(), 0.0005);
}
