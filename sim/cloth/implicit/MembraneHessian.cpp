#include "sim/cloth/implicit/MembraneHessian.h"

#include <array>
#include <cmath>

namespace figment {

using Matrix32 = Eigen::Matrix<double, 3, 2>;

Eigen::Matrix2d positivePart(const Eigen::Matrix2d& S) {
  const double mean = 0.5 * (S(0, 0) + S(1, 1));
  const double radius = std::hypot(0.5 * (S(0, 0) - S(1, 1)), S(0, 1));
  const double high = mean + radius, low = mean - radius;
  if (low >= 0.0) return S;
  if (high <= 0.0) return Eigen::Matrix2d::Zero();
  // S - low I = (high - low) u u^T, u the eigenvector of `high`.
  return high / (high - low) * (S - low * Eigen::Matrix2d::Identity());
}

namespace {
Matrix32 deformation(const Triangle& c, const std::vector<Vec3>& x, const Eigen::Matrix2d& restInverse) {
  Matrix32 D;
  D.col(0) = x[c[1]] - x[c[0]];
  D.col(1) = x[c[2]] - x[c[0]];
  return D * restInverse;
}
}  // namespace

void membraneContribution(const MembraneElement& section, const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                          const PlaneStressLaw& law, double tauDamping, const SystemWeights& weights,
                          const ElementOutput& out) {
  const Triangle& c = section.corners();
  const Eigen::Matrix2d& R = section.restInverse();
  const std::array<Eigen::Vector2d, 3> beta{-(R.row(0) + R.row(1)).transpose(), R.row(0).transpose(),
                                            R.row(1).transpose()};
  const Matrix32 F = deformation(c, x, R);
  const Vec3 f0 = F.col(0), f1 = F.col(1);
  std::array<Eigen::Matrix3d, 3> B;
  for (int a = 0; a < 3; ++a) {
    B[a].row(0) = beta[a][0] * f0.transpose();
    B[a].row(1) = beta[a][1] * f1.transpose();
    B[a].row(2) = 0.5 * (beta[a][0] * f1 + beta[a][1] * f0).transpose();
  }
  const Eigen::Vector3d strain(0.5 * (f0.squaredNorm() - 1.0), 0.5 * (f1.squaredNorm() - 1.0), 0.5 * f0.dot(f1));
  Eigen::Vector3d stressStrain = strain;  // e + tau e'
  if (tauDamping > 0.0)
    for (int a = 0; a < 3; ++a) stressStrain += tauDamping * (B[a] * v[c[a]]);
  const double volume = section.restArea() * law.thickness();
  const Eigen::Matrix3d& C = law.tangent();
  const Eigen::Vector3d stress = C * stressStrain;  // (S_uu, S_vv, 2 S_uv)
  const PlaneStress elastic = law.stress(strain);
  Eigen::Matrix2d S;
  S << elastic.sigmaU, elastic.tauUV, elastic.tauUV, elastic.sigmaV;
  const Eigen::Matrix2d Splus = positivePart(S);
  const double materialWeight = weights.damping * tauDamping + weights.stiffness;
  for (int a = 0; a < 3; ++a) {
    out.force[a] = -volume * (B[a].transpose() * stress);
    out.stiffnessTimesVelocity[a].setZero();
    const Eigen::Matrix3d BaC = volume * B[a].transpose() * C;
    for (int b = 0; b < 3; ++b) {
      const Eigen::Matrix3d materialPart = BaC * B[b];
      const double geometricPart = volume * beta[a].dot(Splus * beta[b]);
      out.stiffnessTimesVelocity[a] += materialPart * v[c[b]] + geometricPart * v[c[b]];
      out.blocks[3 * a + b] = materialWeight * materialPart;
      out.blocks[3 * a + b].diagonal().array() += weights.stiffness * geometricPart;
    }
  }
}

}  // namespace figment
