// Plate bending from the joints' angles: forces are minus the energy's gradient, a curved
// rest shape is at rest, a cylindrical bend of curvature kappa stores D kappa^2 / 2 per
// area on right-triangle and equilateral meshes, in either direction; the stiffness is
// minus the forces' derivative where Gauss-Newton is exact, and the joint-wise form
// bounds the section-wise one.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <random>

#include "sim/cloth/PlateBending.h"
#include "support/FiniteDifferences.h"
#include "support/TestMeshes.h"

using namespace figment;

namespace {
// Rolls a flat mesh in the x-z plane (y = 0) onto a cylinder of radius r whose axis runs
// along z: arc length along x is kept, so the bend is isometric with curvature 1/r.
std::vector<Vec3> rolledAlongX(const std::vector<Vec3>& flat, double r) {
  std::vector<Vec3> x;
  for (const Vec3& p : flat) x.emplace_back(r * std::sin(p.x() / r), r * (1.0 - std::cos(p.x() / r)), p.z());
  return x;
}
std::vector<Vec3> swapXZ(std::vector<Vec3> x) {
  for (Vec3& p : x) std::swap(p.x(), p.z());
  return x;
}
// The bending forces at x.
std::vector<Vec3> jointForces(const PlateBending& bending, const std::vector<Vec3>& x) {
  std::vector<Vec3> force(x.size(), Vec3::Zero());
  bending.addForces(x, force);
  return force;
}
// The stiffness K (weights: stiffness 1) as a dense matrix, in either form.
Eigen::MatrixXd stiffness(const PlateBending& bending, const std::vector<Vec3>& x, bool jointWise) {
  const int n = static_cast<int>(x.size());
  std::vector<double> changes(bending.joints().size());
  std::vector<AngleGradient> gradients(bending.joints().size());
  for (size_t j = 0; j < bending.joints().size(); ++j) changes[j] = bending.joints()[j].measure(x, gradients[j]);
  std::vector<Eigen::Vector3d> moments;
  for (size_t s = 0; s < bending.sectionForms().size(); ++s)
    moments.push_back(bending.sectionMoments(static_cast<int>(s), changes));
  const std::vector<Vec3> still(n, Vec3::Zero());
  const SystemWeights weights{0.0, 0.0, 1.0};
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  auto add = [&](const std::vector<int>& nodes, const std::array<Block3, 36>& blocks) {
    const int k = static_cast<int>(nodes.size());
    for (int a = 0; a < k; ++a)
      for (int b = 0; b < k; ++b) K.block<3, 3>(3 * nodes[a], 3 * nodes[b]) += blocks[a * k + b];
  };
  std::array<Vec3, 6> force, Kv;
  std::array<Block3, 36> blocks;
  if (jointWise)
    for (int j = 0; j < static_cast<int>(bending.joints().size()); ++j) {
      bending.jointStiffness(j, gradients[j], moments, still, weights, {force.data(), Kv.data(), blocks.data()});
      const std::array<int, 4>& c = bending.joints()[j].corners();
      add({c.begin(), c.end()}, blocks);
    }
  else
    for (int s = 0; s < static_cast<int>(bending.sectionForms().size()); ++s) {
      bending.sectionStiffness(s, gradients, moments[s], still, weights, {force.data(), Kv.data(), blocks.data()});
      add(bending.stencilNodes(s), blocks);
    }
  return K;
}

// A 4 x 4 grid curved into a shallow cylinder (rest angles not zero).
TriangleMesh curvedSheet() {
  TriangleMesh sheet = meshes::grid(4, 4, 0.1, 0.1, Vec3(-0.05, 0.05, 0), Vec3::UnitX(), -Vec3::UnitY());
  for (Vec3& x : sheet.vertices) x.z() = 2.0 * x.x() * x.x();
  return sheet;
}

double area(const TriangleMesh& mesh) {
  double total = 0.0;
  for (const Triangle& t : mesh.triangles)
    total += 0.5 * (mesh.vertices[t[1]] - mesh.vertices[t[0]]).cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]).norm();
  return total;
}
}  // namespace

TEST(PlateBending, ForcesAreMinusTheEnergyGradient) {
  // A 3 x 3 grid rolled onto a cylinder at rest, then twisted out of it.
  TriangleMesh rest = meshes::grid(3, 3, 0.03, 0.03, Vec3::Zero(), Vec3::UnitX(), Vec3::UnitZ());
  rest.vertices = rolledAlongX(rest.vertices, 0.05);
  const PlateBending bending(rest, 2e-5, 0.3);
  std::vector<Vec3> force(rest.vertices.size(), Vec3::Zero());
  bending.addForces(rest.vertices, force);
  for (const Vec3& f : force) EXPECT_LT(f.norm(), 1e-15) << "the rest shape is at rest";
  EXPECT_NEAR(bending.energy(rest.vertices), 0.0, 1e-20);

  std::vector<Vec3> x = rest.vertices;
  for (size_t i = 0; i < x.size(); ++i) x[i].y() += 0.004 * std::sin(7.0 * i) + 0.1 * x[i].x() * x[i].z() / 0.03;
  std::fill(force.begin(), force.end(), Vec3::Zero());
  bending.addForces(x, force);
  const auto gradient =
      meshes::numericalGradient([&](const std::vector<Vec3>& p) { return bending.energy(p); }, x, 1e-8);
  for (size_t i = 0; i < x.size(); ++i)
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(force[i][k], -gradient[i][k], 1e-6 * force[i].norm() + 1e-12) << "node " << i << " axis " << k;
  EXPECT_GT(bending.energy(x), 0.0);
}

TEST(PlateBending, AClampDoesNotBendAndItsFreeNeighbourTakesTheWholeAngle) {
  // Two sections folded by theta on their joint: unheld, each sees theta over its own
  // area. Holding one section's corners makes it a clamp: it stores nothing and the free
  // section counts the angle twice (its mid-edge normal is the clamp's), so the energy
  // doubles: 2 x (D/2) A (w theta)^2 -> (D/2) A (2 w theta)^2. Forces stay -grad W.
  const double D = 1e-4, theta = 0.3;
  TriangleMesh pair;
  pair.vertices = {Vec3(0, 0, 0), Vec3(0, 0, -1), Vec3(-1, 0, -0.5), Vec3(std::cos(theta), std::sin(theta), -0.5)};
  pair.triangles = {{0, 1, 2}, {1, 0, 3}};
  TriangleMesh flat = pair;
  flat.vertices[3] = Vec3(1, 0, -0.5);
  PlateBending bending(flat, D, 0.0);
  const double free = bending.energy(pair.vertices);
  EXPECT_GT(free, 0.0);
  bending.hold({1, 1, 1, 0});
  const double clamped = bending.energy(pair.vertices);
  EXPECT_NEAR(clamped, 2.0 * free, 1e-12 * free);
  std::vector<Vec3> force(4, Vec3::Zero());
  bending.addForces(pair.vertices, force);
  const auto gradient =
      meshes::numericalGradient([&](const std::vector<Vec3>& p) { return bending.energy(p); }, pair.vertices, 1e-7);
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(force[i][k], -gradient[i][k], 1e-6 * clamped) << "node " << i;
}

TEST(PlateBending, CylindricalBendStoresHalfDKappaSquaredPerArea) {
  // D kappa^2 / 2 per area, whatever the triangles' shape or the bend's direction. The
  // sections along the two edges the bend runs into have no joint there (a free edge
  // carries no moment), so the energy misses about one column of sections in n.
  const double D = 2e-5, r = 0.2, expectedDensity = 0.5 * D / (r * r);
  const int n = 40;
  const TriangleMesh grid = meshes::grid(n, n, 0.2, 0.2, Vec3::Zero(), Vec3::UnitX(), Vec3::UnitZ());
  const TriangleMesh equilateral = meshes::equilateralStrip(n, n, 0.2 / n, Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitX());
  for (const TriangleMesh* mesh : {&grid, &equilateral}) {
    const PlateBending bending(*mesh, D, 0.3);
    const double expected = expectedDensity * area(*mesh);
    const double alongX = bending.energy(rolledAlongX(mesh->vertices, r));
    const double alongZ = bending.energy(swapXZ(rolledAlongX(swapXZ(mesh->vertices), r)));
    for (double energy : {alongX, alongZ}) {
      EXPECT_LT(energy, expected * 1.01) << (mesh == &grid ? "grid" : "equilateral");
      EXPECT_GT(energy, expected * (1.0 - 1.5 / n) * 0.99) << (mesh == &grid ? "grid" : "equilateral");
    }
  }
}

TEST(PlateBending, ASaddleCostsEnergy) {
  // Opposite curvatures in two directions cancel in the mean curvature but not in the
  // plate energy: (D/2)(1 - nu)(kappa1^2 + kappa2^2) per area for tr dS = 0.
  const int n = 20;
  TriangleMesh flat = meshes::grid(n, n, 0.1, 0.1, Vec3(-0.05, 0, -0.05), Vec3::UnitX(), Vec3::UnitZ());
  const double D = 2e-5, nu = 0.3, k = 2.0;
  const PlateBending bending(flat, D, nu);
  std::vector<Vec3> saddle = flat.vertices;
  for (Vec3& p : saddle) p.y() = 0.5 * k * (p.x() * p.x() - p.z() * p.z());
  const double expected = 0.5 * D * (1 - nu) * 2 * k * k * area(flat);
  // The discretisation bound of the rolled sheets above: the rim's vertices lack the
  // hinges beyond them, so the grid holds between 1 - 1.5/n of the energy and all of it
  // (it holds 96.1 %), 1 % either way for the hinges' own error.
  EXPECT_LT(bending.energy(saddle), expected * 1.01);
  EXPECT_GT(bending.energy(saddle), expected * (1.0 - 1.5 / n) * 0.99);
}

TEST(PlateBending, StiffnessIsMinusTheForceDerivativeAtTheRestAngles) {
  // Moved rigidly, the sheet keeps its rest angles: d = 0, where Gauss-Newton is exact
  // and the curvature bound vanishes, so K = -df/dx.
  const TriangleMesh rest = curvedSheet();
  const PlateBending bending(rest, 2e-5, 0.3);
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(0.3, Vec3(1, -1, 2).normalized()).toRotationMatrix();
  std::vector<Vec3> x;
  for (const Vec3& p : rest.vertices) x.push_back(rotation * p + Vec3(0.01, 0.02, -0.03));
  const Eigen::MatrixXd K = stiffness(bending, x, false);
  const Eigen::MatrixXd numerical =
      meshes::numericalJacobian([&](const std::vector<Vec3>& p) { return jointForces(bending, p); }, x, 1e-7);
  ASSERT_GT(K.norm(), 0.0);
  EXPECT_LT((K + numerical).norm(), 1e-6 * K.norm());
}

TEST(PlateBending, TheJointWiseStiffnessBoundsTheSectionWiseOne) {
  // On a bent sheet, w^T K_joints w >= w^T K_sections w for every w (random ones here).
  const TriangleMesh rest = curvedSheet();
  const PlateBending bending(rest, 2e-5, 0.3);
  std::vector<Vec3> x = rest.vertices;
  for (Vec3& p : x) p.z() -= 3.0 * p.y() * p.y();
  const Eigen::MatrixXd joints = stiffness(bending, x, true), sections = stiffness(bending, x, false);
  std::mt19937_64 random(5);
  std::normal_distribution<double> normal;
  for (int trial = 0; trial < 20; ++trial) {
    Eigen::VectorXd w(joints.rows());
    for (int i = 0; i < w.size(); ++i) w[i] = normal(random);
    EXPECT_GE(w.dot(joints * w), w.dot(sections * w) * (1.0 - 1e-12)) << trial;
  }
}
