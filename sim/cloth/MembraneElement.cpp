#include "sim/cloth/MembraneElement.h"

#include <Eigen/Dense>

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
}  // namespace

Eigen::Vector3d MembraneElement::strain(const std::vector<Vec3>& x) const {
  const Matrix32 F = edgeMatrix(corners_, x) * restInverse_;
  const Eigen::Matrix2d E = 0.5 * (F.transpose() * F - Eigen::Matrix2d::Identity());
  return {E(0, 0), E(1, 1), E(0, 1)};
}

double MembraneElement::energy(const std::vector<Vec3>& x, const PlaneStressLaw& law) const {
  return restArea_ * law.thickness() * law.energyDensity(strain(x));
}

bool MembraneElement::addForces(const std::vector<Vec3>& x, const std::vector<Vec3>& v, const PlaneStressLaw& law,
                                double tauDamping, double strainLimit, std::vector<Vec3>& force) const {
  const Matrix32 F = edgeMatrix(corners_, x) * restInverse_;
  const Eigen::Matrix2d FtF = F.transpose() * F;
  Eigen::Vector3d e(0.5 * (FtF(0, 0) - 1.0), 0.5 * (FtF(1, 1) - 1.0), 0.5 * FtF(0, 1));
  bool clamped = false;
  if (strainLimit > 0.0) {
    clamped = e.cwiseAbs().maxCoeff() > strainLimit;
    if (clamped) e = e.cwiseMax(-strainLimit).cwiseMin(strainLimit);
  }
  if (tauDamping > 0.0) {
    const Matrix32 Fdot = edgeMatrix(corners_, v) * restInverse_;
    const Eigen::Matrix2d rate = 0.5 * (Fdot.transpose() * F + F.transpose() * Fdot);
    e += tauDamping * Eigen::Vector3d(rate(0, 0), rate(1, 1), rate(0, 1));
  }
  addStressForces(F, e, law, force);
  return clamped;
}

void MembraneElement::addStressForces(const Matrix32& F, const Eigen::Vector3d& e, const PlaneStressLaw& law,
                                      std::vector<Vec3>& force) const {
  const PlaneStress s = law.stress(e);
  Eigen::Matrix2d S;
  S << s.sigmaU, s.tauUV, s.tauUV, s.sigmaV;
  const Matrix32 H = -(restArea_ * law.thickness()) * F * S * restInverse_.transpose();
  force[corners_[1]] += H.col(0);
  force[corners_[2]] += H.col(1);
  force[corners_[0]] -= H.col(0) + H.col(1);
}

void MembraneElement::addDampingForces(const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                                       const PlaneStressLaw& law, double tauDamping, std::vector<Vec3>& force) const {
  if (!(tauDamping > 0.0)) return;
  const Matrix32 F = edgeMatrix(corners_, x) * restInverse_;
  const Matrix32 Fdot = edgeMatrix(corners_, v) * restInverse_;
  const Eigen::Matrix2d rate = 0.5 * (Fdot.transpose() * F + F.transpose() * Fdot);
  addStressForces(F, tauDamping * Eigen::Vector3d(rate(0, 0), rate(1, 1), rate(0, 1)), law, force);
}

}  // namespace figment
