// The implicit integrator's forces and Hessian: the same forces as the explicit model
// (ClothModel), and a stiffness matrix K = -df/dx that matches central differences of
// those forces where the projection does not act.
#include "support/FiniteDifferences.h"
#include "support/TestMeshes.h"
#include "sim/cloth/implicit/ImplicitSystem.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <random>

using namespace figment;

namespace {
std::vector<Vec3> randomVectors(size_t n, double scale, std::mt19937_64& random) {
  std::uniform_real_distribution<double> uniform(-scale, scale);
  std::vector<Vec3> out(n);
  for (Vec3& value : out) value = Vec3(uniform(random), uniform(random), uniform(random));
  return out;
}

double largestNorm(const std::vector<Vec3>& values) {
  double largest = 0.0;
  for (const Vec3& value : values) largest = std::max(largest, value.norm());
  return largest;
}

// A 10 cm sheet of 4 x 4 quads, curved into a shallow cylinder (so its rest angles are
// not zero).
TriangleMesh curvedSheet() {
  TriangleMesh sheet = meshes::grid(4, 4, 0.1, 0.1, Vec3(-0.05, 0.05, 0), Vec3::UnitX(), -Vec3::UnitY());
  for (Vec3& x : sheet.vertices) x.z() = 2.0 * x.x() * x.x();
  return sheet;
}
}  // namespace

TEST(ImplicitSystem, ForcesEqualTheExplicitModels) {
  // A deformed, moving sheet in the wind: f = m a of ClothModel, node by node.
  ClothParameters p;
  p.wind.amplitude = 3.0;
  p.wind.direction = Vec3(1.0, 0.2, 0.5);
  p.strainRateDamping = 2e-3;
  const TriangleMesh sheet = curvedSheet();
  std::mt19937_64 random(7);
  std::vector<Vec3> x = sheet.vertices;
  const std::vector<Vec3> offsets = randomVectors(x.size(), 0.004, random);
  for (size_t i = 0; i < x.size(); ++i) x[i] += offsets[i];
  const std::vector<Vec3> v = randomVectors(x.size(), 0.5, random);
  const ClothModel model(sheet, p);
  std::vector<Vec3> a;
  model.accelerations(x, v, 0.3, a);
  ImplicitSystem system(model, p);
  system.assemble(x, v, 0.3, SystemWeights{});
  const double scale = largestNorm(system.forces());
  ASSERT_GT(scale, 1e-3);
  for (size_t i = 0; i < x.size(); ++i)
    EXPECT_LT((system.forces()[i] - model.masses()[i] * a[i]).norm(), 1e-10 * scale) << "node " << i;
}

TEST(ImplicitSystem, StiffnessMatchesFiniteDifferencesOfTheForces) {
  // The curved sheet scaled by 4 % (stretched alike in every direction, so S > 0 and the
  // projection leaves K exact) and moved: its angles are the rest angles, where the
  // Gauss-Newton bending stiffness is exact too. w^T K = -d(w . f)/dx for random w.
  ClothParameters p;
  p.implicitSolver.bending = BendingStiffness::Sections;
  p.strainRateDamping = 0.0;
  p.material.thickness = 0.002;  // bending of the same order as the membrane's geometric term
  const TriangleMesh sheet = curvedSheet();
  std::vector<Vec3> x = sheet.vertices;
  for (Vec3& xi : x) xi = 1.04 * xi + Vec3(0.01, -0.02, 0.03);
  const std::vector<Vec3> still(x.size(), Vec3::Zero());
  const ClothModel model(sheet, p);
  ImplicitSystem system(model, p);
  std::mt19937_64 random(11);
  for (int trial = 0; trial < 3; ++trial) {
    const std::vector<Vec3> w = randomVectors(x.size(), 1.0, random);
    auto work = [&](const std::vector<Vec3>& at) {
      system.assemble(at, still, 0.0, SystemWeights{0.0, 0.0, 1.0});
      double sum = 0.0;
      for (size_t i = 0; i < at.size(); ++i) sum += w[i].dot(system.forces()[i]);
      return sum;
    };
    const std::vector<Vec3> numerical = meshes::numericalGradient(work, x, 1e-7);
    system.assemble(x, still, 0.0, SystemWeights{0.0, 0.0, 1.0});
    std::vector<Vec3> Kw;
    system.matrix().multiply(w, Kw);
    const double scale = largestNorm(Kw);
    for (size_t i = 0; i < x.size(); ++i)
      EXPECT_LT((Kw[i] + numerical[i]).norm(), 1e-6 * scale) << "node " << i << ", trial " << trial;
  }
}

namespace {
double quadraticForm(const BlockSparseMatrix& A, const std::vector<Vec3>& w) {
  std::vector<Vec3> Aw;
  A.multiply(w, Aw);
  double sum = 0.0;
  for (size_t i = 0; i < w.size(); ++i) sum += w[i].dot(Aw[i]);
  return sum;
}
}  // namespace

TEST(ImplicitSystem, JointBendingBoundsTheSectionsStiffnessWithTheSameForces) {
  // The joint-wise bound (the default) against the exact Gauss-Newton form on a bent,
  // moving sheet: the same forces; w^T K_joints w >= w^T K_sections w for every w
  // (random ones, and the sheet's own bending mode), and not more than 3x it on that mode.
  ClothParameters p;
  p.material.thickness = 0.002;
  const TriangleMesh sheet = curvedSheet();
  std::vector<Vec3> x = sheet.vertices;
  for (Vec3& xi : x) xi.z() -= 3.0 * xi.y() * xi.y();  // bent across its rest curvature
  std::mt19937_64 random(5);
  const std::vector<Vec3> v = randomVectors(x.size(), 0.2, random);
  const ClothModel model(sheet, p);
  ImplicitSystem joints(model, p);
  p.implicitSolver.bending = BendingStiffness::Sections;
  ImplicitSystem sections(model, p);
  const SystemWeights stiffnessOnly{0.0, 0.0, 1.0};
  joints.assemble(x, v, 0.0, stiffnessOnly);
  sections.assemble(x, v, 0.0, stiffnessOnly);
  EXPECT_LT(joints.matrix().blockCount(), sections.matrix().blockCount());
  const double scale = largestNorm(sections.forces());
  for (size_t i = 0; i < x.size(); ++i)
    EXPECT_LT((joints.forces()[i] - sections.forces()[i]).norm(), 1e-12 * scale) << "node " << i;
  for (int trial = 0; trial < 20; ++trial) {
    const std::vector<Vec3> w = randomVectors(x.size(), 1.0, random);
    EXPECT_GE(quadraticForm(joints.matrix(), w), quadraticForm(sections.matrix(), w) * (1.0 - 1e-12)) << trial;
  }
  std::vector<Vec3> mode(x.size());
  for (size_t i = 0; i < x.size(); ++i) mode[i] = Vec3(0.0, 0.0, x[i].x() * x[i].x());
  const double exact = quadraticForm(sections.matrix(), mode), bound = quadraticForm(joints.matrix(), mode);
  EXPECT_GE(bound, exact);
  EXPECT_LT(bound, 3.0 * exact);
}

TEST(ImplicitSystem, CompressedSectionsKeepThePositiveSemiDefiniteStiffness) {
  // A sheet crumpled at random (compressed and stretched sections): every eigenvalue of
  // the assembled K (dense here) is >= 0 within rounding.
  ClothParameters p;
  const TriangleMesh sheet = meshes::grid(3, 3, 0.06, 0.06);
  std::mt19937_64 random(3);
  std::vector<Vec3> x = sheet.vertices;
  const std::vector<Vec3> offsets = randomVectors(x.size(), 0.01, random);
  for (size_t i = 0; i < x.size(); ++i) x[i] = 0.9 * x[i] + offsets[i];
  const ClothModel model(sheet, p);
  ImplicitSystem system(model, p);
  system.assemble(x, std::vector<Vec3>(x.size(), Vec3::Zero()), 0.0, SystemWeights{0.0, 0.0, 1.0});
  const int n = static_cast<int>(x.size());
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  const BlockSparseMatrix& A = system.matrix();
  for (int i = 0; i < n; ++i)
    for (int k = A.rowStart(i); k < A.rowStart(i + 1); ++k) K.block<3, 3>(3 * i, 3 * A.column(k)) = A.block(k);
  EXPECT_LT((K - K.transpose()).norm(), 1e-9 * K.norm());
  const Eigen::VectorXd eigenvalues = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(K).eigenvalues();
  EXPECT_GT(eigenvalues.minCoeff(), -1e-9 * eigenvalues.maxCoeff());
}
