// The model every integrator asks: its stiffness K = -df/dx and damping D = -df/dv
// match central differences of its forces where the projections do not act, the
// joint-wise bending stiffness bounds the section-wise one with the same forces, K stays
// positive semi-definite on a crumpled sheet, the requests' forces add up, and the
// matrix holds the lumped masses.
#include <gtest/gtest.h>

#include <random>

#include "sim/cloth/ClothModel.h"
#include "support/Eigenvalues.h"
#include "support/FiniteDifferences.h"
#include "support/TestMeshes.h"

namespace test_ClothModel {

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

ClothModel::Evaluation evaluated(const ClothModel& model, const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                                 ClothModel::Request request, const SystemWeights* weights = nullptr) {
  request.system = weights;
  ClothModel::Evaluation out;
  model.evaluate(x, v, 0.3, request, out);
  return out;
}

Eigen::MatrixXd dense(const BlockSparseMatrix& A) {
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(3 * A.rows(), 3 * A.rows());
  for (int i = 0; i < A.rows(); ++i)
    for (int k = A.rowStart(i); k < A.rowStart(i + 1); ++k) M.block<3, 3>(3 * i, 3 * A.column(k)) = A.block(k);
  return M;
}

double quadraticForm(const BlockSparseMatrix& A, const std::vector<Vec3>& w) {
  std::vector<Vec3> Aw;
  A.multiply(w, Aw);
  double sum = 0.0;
  for (size_t i = 0; i < w.size(); ++i) sum += w[i].dot(Aw[i]);
  return sum;
}
}  // namespace

TEST(ClothModel, StiffnessIsMinusTheForceDerivative) {
  // The curved sheet scaled by 4 % (stretched alike in every direction, so S > 0 and the
  // projection leaves K exact) and moved: its angles are the rest angles, where the
  // Gauss-Newton bending stiffness is exact too.
  ClothParameters p;
  p.implicitSolver.bending = BendingStiffness::Sections;
  p.strainRateDamping = 0.0;
  p.material.thickness = 0.002;  // bending of the same order as the membrane's geometric term
  const TriangleMesh sheet = curvedSheet();
  std::vector<Vec3> x = sheet.vertices;
  for (Vec3& xi : x) xi = 1.04 * xi + Vec3(0.01, -0.02, 0.03);
  const std::vector<Vec3> still(x.size(), Vec3::Zero());
  const ClothModel model(sheet, p);
  const SystemWeights stiffness{0.0, 0.0, 1.0};
  const Eigen::MatrixXd K = dense(evaluated(model, x, still, {}, &stiffness).matrix);
  const Eigen::MatrixXd numerical = meshes::numericalJacobian(
      [&](const std::vector<Vec3>& at) { return evaluated(model, at, still, {}).forces; }, x, 1e-8);
  EXPECT_LT((K + numerical).norm(), 1e-6 * K.norm());
}

TEST(ClothModel, DampingIsMinusTheForceDerivativeInVelocity) {
  // Strain-rate damping and air: the forces are linear in v, so D = -df/dv exactly
  // (the wind's derivative is left out: no wind here).
  ClothParameters p;
  p.strainRateDamping = 2e-3;
  p.airResistance = 3.0;
  const TriangleMesh sheet = curvedSheet();
  std::mt19937_64 random(7);
  std::vector<Vec3> x = sheet.vertices;
  const std::vector<Vec3> offsets = randomVectors(x.size(), 0.004, random);
  for (size_t i = 0; i < x.size(); ++i) x[i] += offsets[i];
  const std::vector<Vec3> v = randomVectors(x.size(), 0.5, random);
  const ClothModel model(sheet, p);
  const SystemWeights damping{0.0, 1.0, 0.0};
  const Eigen::MatrixXd D = dense(evaluated(model, x, v, {}, &damping).matrix);
  const Eigen::MatrixXd numerical =
      meshes::numericalJacobian([&](const std::vector<Vec3>& w) { return evaluated(model, x, w, {}).forces; }, v, 1e-4);
  EXPECT_LT((D + numerical).norm(), 1e-8 * D.norm());
}

TEST(ClothModel, TheMatrixHoldsTheMassesAndKvIsTheStiffnessTimesV) {
  const TriangleMesh sheet = curvedSheet();
  std::mt19937_64 random(9);
  const std::vector<Vec3> v = randomVectors(sheet.vertices.size(), 0.5, random);
  std::vector<Vec3> x = sheet.vertices;
  for (Vec3& xi : x) xi *= 1.02;
  const ClothModel model(sheet, ClothParameters{});
  const SystemWeights mass{1.0, 0.0, 0.0}, stiffness{0.0, 0.0, 1.0};
  const Eigen::MatrixXd M = dense(evaluated(model, x, v, {}, &mass).matrix);
  Eigen::VectorXd masses(M.rows());
  for (size_t i = 0; i < x.size(); ++i) masses.segment<3>(3 * i).setConstant(model.masses()[i]);
  EXPECT_EQ(M, Eigen::MatrixXd(masses.asDiagonal()));
  const ClothModel::Evaluation K = evaluated(model, x, v, {}, &stiffness);
  std::vector<Vec3> Kv;
  K.matrix.multiply(v, Kv);
  for (size_t i = 0; i < x.size(); ++i)
    EXPECT_LT((K.stiffnessTimesVelocity[i] - Kv[i]).norm(), 1e-12 * largestNorm(Kv)) << "node " << i;
}

TEST(ClothModel, TheRequestsForcesAddUp) {
  // What accelerations() asks in two passes under a limiter (elastic; damping, wind and
  // air) adds up to what it asks in one without, and gravity is m g.
  ClothParameters p;
  p.wind.amplitude = 3.0;
  p.wind.direction = Vec3(1.0, 0.2, 0.5);
  p.strainRateDamping = 2e-3;
  const TriangleMesh sheet = curvedSheet();
  std::mt19937_64 random(3);
  std::vector<Vec3> x = sheet.vertices;
  const std::vector<Vec3> offsets = randomVectors(x.size(), 0.004, random);
  for (size_t i = 0; i < x.size(); ++i) x[i] += offsets[i];
  const std::vector<Vec3> v = randomVectors(x.size(), 0.5, random);
  const ClothModel model(sheet, p);
  ClothModel::Request elastic, rest, all;
  elastic.damping = elastic.external = elastic.weight = false;
  rest.elastic = rest.weight = false;
  const std::vector<Vec3> a = evaluated(model, x, v, elastic).forces, b = evaluated(model, x, v, rest).forces;
  const std::vector<Vec3> sum = evaluated(model, x, v, all).forces;
  const double scale = largestNorm(sum);
  ASSERT_GT(largestNorm(b), 1e-3 * scale);
  for (size_t i = 0; i < x.size(); ++i)
    EXPECT_LT((a[i] + b[i] + model.nodes().weight(i) - sum[i]).norm(), 1e-12 * scale) << "node " << i;
}

TEST(ClothModel, JointBendingBoundsTheSectionsStiffnessWithTheSameForces) {
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
  const ClothModel jointModel(sheet, p);
  p.implicitSolver.bending = BendingStiffness::Sections;
  const ClothModel sectionModel(sheet, p);
  const SystemWeights stiffnessOnly{0.0, 0.0, 1.0};
  const ClothModel::Evaluation joints = evaluated(jointModel, x, v, {}, &stiffnessOnly);
  const ClothModel::Evaluation sections = evaluated(sectionModel, x, v, {}, &stiffnessOnly);
  EXPECT_LT(joints.matrix.blockCount(), sections.matrix.blockCount());
  for (size_t i = 0; i < x.size(); ++i) EXPECT_EQ(joints.forces[i], sections.forces[i]) << "node " << i;
  for (int trial = 0; trial < 20; ++trial) {
    const std::vector<Vec3> w = randomVectors(x.size(), 1.0, random);
    EXPECT_GE(quadraticForm(joints.matrix, w), quadraticForm(sections.matrix, w) * (1.0 - 1e-12)) << trial;
  }
  std::vector<Vec3> mode(x.size());
  for (size_t i = 0; i < x.size(); ++i) mode[i] = Vec3(0.0, 0.0, x[i].x() * x[i].x());
  const double exact = quadraticForm(sections.matrix, mode), bound = quadraticForm(joints.matrix, mode);
  EXPECT_GE(bound, exact);
  EXPECT_LT(bound, 3.0 * exact);
}

TEST(ClothModel, CompressedSectionsKeepThePositiveSemiDefiniteStiffness) {
  // A sheet crumpled at random (compressed and stretched sections): every eigenvalue of
  // the assembled K is >= 0 within rounding.
  const TriangleMesh sheet = meshes::grid(3, 3, 0.06, 0.06);
  std::mt19937_64 random(3);
  std::vector<Vec3> x = sheet.vertices;
  const std::vector<Vec3> offsets = randomVectors(x.size(), 0.01, random);
  for (size_t i = 0; i < x.size(); ++i) x[i] = 0.9 * x[i] + offsets[i];
  const ClothModel model(sheet, ClothParameters{});
  const SystemWeights stiffnessOnly{0.0, 0.0, 1.0};
  const Eigen::MatrixXd K =
      dense(evaluated(model, x, std::vector<Vec3>(x.size(), Vec3::Zero()), {}, &stiffnessOnly).matrix);
  EXPECT_LT((K - K.transpose()).norm(), 1e-9 * K.norm());
  const Eigen::VectorXd eigenvalues = test::symmetricEigenvalues(K);
  EXPECT_GT(eigenvalues.minCoeff(), -1e-9 * eigenvalues.maxCoeff());
}

}  // namespace test_ClothModel
