// The node terms: masses and areas lumped a third per corner, a node of degenerate
// sections only floats, gravity is minus the gradient of the potential energy, the air's
// damping is minus the derivative of its force in the velocity (central differences),
// and the wind's corner forces add up to p A |n . w| w.
#include <gtest/gtest.h>

#include "sim/cloth/NodeTerms.h"
#include "support/FiniteDifferences.h"

using namespace figment;

namespace {
// Two sections sharing the edge 1-2; node 4 belongs only to a degenerate section.
struct Garment {
  std::vector<Vec3> x = {Vec3(0, 0, 0), Vec3(0.1, 0, 0), Vec3(0, 0.2, 0), Vec3(0.1, 0.2, 0.05), Vec3(0.3, 0, 0)};
  std::vector<MembraneElement> sections;
  Garment() {
    for (const Triangle& t : {Triangle{0, 1, 2}, Triangle{1, 3, 2}})
      sections.emplace_back(t, x[t[0]], x[t[1]], x[t[2]]);
  }
};

ClothParameters parameters() {
  ClothParameters p;
  p.airResistance = 2.0;
  p.gravity = Vec3(0.0, -9.81, 0.5);
  return p;
}
}  // namespace

TEST(NodeTerms, MassesAndAreasAreAThirdOfEachSectionPerCorner) {
  const Garment g;
  const ClothParameters p = parameters();
  const NodeTerms nodes(g.sections, g.x.size(), p);
  const double a0 = g.sections[0].restArea(), a1 = g.sections[1].restArea();
  const double rhoH = p.material.arealDensity();
  EXPECT_NEAR(nodes.masses()[0], rhoH * a0 / 3, 1e-15);
  EXPECT_NEAR(nodes.masses()[1], rhoH * (a0 + a1) / 3, 1e-15);
  EXPECT_NEAR(nodes.masses()[3], rhoH * a1 / 3, 1e-15);
  EXPECT_NEAR(nodes.inverseMass(1), 1.0 / nodes.masses()[1], 1e-9);
  EXPECT_NEAR(nodes.drag(1, Vec3::UnitX()).x(), p.airResistance * (a0 + a1) / 3, 1e-15);
  EXPECT_FALSE(nodes.floats(0));
  EXPECT_TRUE(nodes.floats(4));  // no section: no mass, moved by gravity alone
  EXPECT_EQ(nodes.masses()[4], 0.0);
  EXPECT_EQ(nodes.inverseMass(4), 0.0);
}

TEST(NodeTerms, GravityIsMinusThePotentialGradient) {
  const Garment g;
  const NodeTerms nodes(g.sections, g.x.size(), parameters());
  auto potential = [&](const std::vector<Vec3>& x) {
    double sum = 0.0;
    for (size_t i = 0; i < x.size(); ++i) sum -= nodes.masses()[i] * nodes.gravity().dot(x[i]);
    return sum;
  };
  const std::vector<Vec3> gradient = meshes::numericalGradient(potential, g.x, 1e-6);
  for (size_t i = 0; i < g.x.size(); ++i) EXPECT_LT((nodes.weight(i) + gradient[i]).norm(), 1e-12) << "node " << i;
}

TEST(NodeTerms, AirDampingIsMinusTheForceDerivativeInVelocity) {
  const Garment g;
  const NodeTerms nodes(g.sections, g.x.size(), parameters());
  const std::vector<Vec3> v = {Vec3(0.1, 0, 0), Vec3(0, 0.3, 0), Vec3(0, 0, -0.2), Vec3(1, 1, 1), Vec3(0, 0, 0)};
  auto airForces = [&](const std::vector<Vec3>& w) {
    std::vector<Vec3> f;
    for (size_t i = 0; i < w.size(); ++i) f.push_back(-nodes.drag(i, w[i]));
    return f;
  };
  const Eigen::MatrixXd numerical = meshes::numericalJacobian(airForces, v, 1e-6);
  for (size_t i = 0; i < v.size(); ++i) {
    const double dt = 0.01;  // the weight a backward Euler step gives it
    const Eigen::Matrix3d block = nodes.weightedDragRate(i, dt) * Eigen::Matrix3d::Identity();
    EXPECT_LT((block + dt * numerical.block<3, 3>(3 * i, 3 * i)).norm(), 1e-12) << "node " << i;
  }
}

TEST(NodeTerms, WindCornerForcesAddUpToThePressureTimesTheExposedArea) {
  const Garment g;
  ClothParameters p = parameters();
  p.wind.amplitude = 3.0;
  p.wind.direction = Vec3(0.0, 0.0, 2.0);
  const NodeTerms nodes(g.sections, g.x.size(), p);
  ASSERT_TRUE(nodes.wind().blows());
  // Section 0 lies in the x-y plane, face-on to a wind along z: it catches p A.
  const Vec3 corner = nodes.windCornerForce(g.sections[0], g.x, 3.0);
  EXPECT_LT((3.0 * corner - 3.0 * g.sections[0].restArea() * Vec3::UnitZ()).norm(), 1e-15);
}
