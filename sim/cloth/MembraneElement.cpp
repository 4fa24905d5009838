#include "sim/cloth/MembraneElement.h"

#include <Eigen/Dense>
#include <cmath>

namespace figment {

using Matrix32 = Eigen::Matrix<double, 3, 2>;

MembraneElement::MembraneElement(const Triangle& corners, const Vec3& X0, const Vec3& X1, const Vec3& X2)
    : corners_(corners) {
  const Vec3 e1 = X1 - X0, e2 = X2 - X0;
  const Vec3 normal = e1.cross(e2);
  const double doubleArea = normal.norm();
  if (!(doubleArea > 0.0) || e1.norm() == 0.0) return;
  const Vec3 u = e1.normalized();
  const Vec3 w = normal.normalized().cross(u);  // in-plane, perpendicular to u
  Eigen::Matrix2d Dm;
  Dm << e1.dot(u), e2.dot(u), e1.dot(w), e2.dot(w);
  restInverse_ = Dm.inverse();
  restArea_ = 0.5 * doubleArea;
}

namespace {
Matrix32 edgeMatrix(const Triangle& c, const std::vector<Vec3>& x) {
  Matrix32 D;
  D.col(0) = x[c[1]] - x[c[0]];
  D.col(1) = x[c[2]] - x[c[0]];
  return D;
}

Eigen::Vector3d greenStrain(const Matrix32& F) {
  const Eigen::Matrix2d FtF = F.transpose() * F;
  return {0.5 * (FtF(0, 0) - 1.0), 0.5 * (FtF(1, 1) - 1.0), 0.5 * FtF(0, 1)};
}

Eigen::Matrix2d stressMatrix(const PlaneStress& s) {
  Eigen::Matrix2d S;
  S << s.sigmaU, s.tauUV, s.tauUV, s.sigmaV;
  return S;
}
}  // namespace

Eigen::Matrix2d positivePart(const Eigen::Matrix2d& S) {
  const double mean = 0.5 * (S(0, 0) + S(1, 1));
  const double radius = std::hypot(0.5 * (S(0, 0) - S(1, 1)), S(0, 1));
  const double high = mean + radius, low = mean - radius;
  if (low >= 0.0) return S;
  if (high <= 0.0) return Eigen::Matrix2d::Zero();
  // S - low I = (high - low) u u^T, u the eigenvector of `high`.
  return high / (high - low) * (S - low * Eigen::Matrix2d::Identity());
}

Eigen::Vector3d MembraneElement::strain(const std::vector<Vec3>& x) const {
  return greenStrain(edgeMatrix(corners_, x) * restInverse_);
}

double MembraneElement::energy(const std::vector<Vec3>& x, const PlaneStressLaw& law) const {
  return restArea_ * law.thickness() * law.energyDensity(strain(x));
}

bool MembraneElement::evaluate(const std::vector<Vec3>& x, const std::vector<Vec3>& v, const PlaneStressLaw& law,
                               const MembraneRequest& request, const SystemWeights* weights,
                               const ElementOutput& out) const {
  const Matrix32 F = edgeMatrix(corners_, x) * restInverse_;
  const Eigen::Vector3d strain = greenStrain(F);
  // The strain the stress is taken of: e (clamped), plus tau e'.
  Eigen::Vector3d e = request.elastic ? strain : Eigen::Vector3d::Zero();
  bool clamped = false;
  if (request.elastic && request.strainLimit > 0.0) {
    clamped = e.cwiseAbs().maxCoeff() > request.strainLimit;
    if (clamped) e = e.cwiseMax(-request.strainLimit).cwiseMin(request.strainLimit);
  }
  if (request.damping > 0.0) {
    const Matrix32 Fdot = edgeMatrix(corners_, v) * restInverse_;
    const Eigen::Matrix2d rate = 0.5 * (Fdot.transpose() * F + F.transpose() * Fdot);
    e += request.damping * Eigen::Vector3d(rate(0, 0), rate(1, 1), rate(0, 1));
  }
  const Eigen::Matrix2d S = stressMatrix(law.stress(e));
  const Matrix32 H = -(restArea_ * law.thickness()) * F * S * restInverse_.transpose();
  out.force[0] = -(H.col(0) + H.col(1));
  out.force[1] = H.col(0);
  out.force[2] = H.col(1);
  if (weights) writeDerivatives(F, strain, v, law, request.damping, *weights, out);
  return clamped;
}

void MembraneElement::writeDerivatives(const Matrix32& F, const Eigen::Vector3d& strain, const std::vector<Vec3>& v,
                                       const PlaneStressLaw& law, double tauDamping, const SystemWeights& weights,
                                       const ElementOutput& out) const {
  const Eigen::Matrix2d& R = restInverse_;
  const std::array<Eigen::Vector2d, 3> beta{-(R.row(0) + R.row(1)).transpose(), R.row(0).transpose(),
                                            R.row(1).transpose()};
  const Vec3 f0 = F.col(0), f1 = F.col(1);
  std::array<Eigen::Matrix3d, 3> B;  // de/dx_a
  for (int a = 0; a < 3; ++a) {
    B[a].row(0) = beta[a][0] * f0.transpose();
    B[a].row(1) = beta[a][1] * f1.transpose();
    B[a].row(2) = 0.5 * (beta[a][0] * f1 + beta[a][1] * f0).transpose();
  }
  const double volume = restArea_ * law.thickness();
  const Eigen::Matrix2d Splus = positivePart(stressMatrix(law.stress(strain)));
  const double materialWeight = weights.damping * tauDamping + weights.stiffness;
  for (int a = 0; a < 3; ++a) {
    out.stiffnessTimesVelocity[a].setZero();
    const Eigen::Matrix3d BaC = volume * B[a].transpose() * law.tangent();
    for (int b = 0; b < 3; ++b) {
      const Eigen::Matrix3d materialPart = BaC * B[b];
      const double geometricPart = volume * beta[a].dot(Splus * beta[b]);
      const Vec3& vb = v[corners_[b]];
      out.stiffnessTimesVelocity[a] += materialPart * vb + geometricPart * vb;
      out.blocks[3 * a + b] = materialWeight * materialPart;
      out.blocks[3 * a + b].diagonal().array() += weights.stiffness * geometricPart;
    }
  }
}

}  // namespace figment
