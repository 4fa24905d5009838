// The broad phase (sim/collision/BroadPhaseCollider.h): body parts far from the garment
// are left out, and every answer is still the whole body's, so a drape is the same with
// it or without it.
#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "sim/cloth/ClothSolver.h"
#include "sim/collision/BroadPhaseCollider.h"
#include "sim/collision/CollisionVolume.h"
#include "sim/collision/CompositeCollider.h"
#include "sim/collision/PlaneCollider.h"
#include "sim/collision/VolumeSetCollider.h"
#include "support/TestCapsules.h"
#include "support/TestMeshes.h"

namespace test_BroadPhaseCollider {

using namespace figment;

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

// A standing figure of capsules: a trunk, two legs, two arms and a head (1.8 m), the
// volumes touching and overlapping at the joints as a mannequin's do.
std::shared_ptr<VolumeSetCollider> capsuleFigure() {
  using test::segmentCapsule;
  const std::vector<CapsuleParameters> capsules = {
      segmentCapsule(Vec3(0, 0.95, 0), Vec3(0, 1.45, 0), 0.15),      // trunk
      segmentCapsule(Vec3(-0.1, 0.1, 0), Vec3(-0.1, 0.9, 0), 0.07),  // legs
      segmentCapsule(Vec3(0.1, 0.1, 0), Vec3(0.1, 0.9, 0), 0.07),
      segmentCapsule(Vec3(-0.2, 1.45, 0), Vec3(-0.25, 0.85, 0), 0.045),  // arms
      segmentCapsule(Vec3(0.2, 1.45, 0), Vec3(0.25, 0.85, 0), 0.045),
      segmentCapsule(Vec3(0, 1.6, 0), Vec3(0, 1.7, 0), 0.1),  // head
  };
  std::vector<PosedCollisionVolume> volumes;
  for (size_t i = 0; i < capsules.size(); ++i)
    volumes.push_back({static_cast<int>(i), makeVolume(capsules[i]), Eigen::Affine3d::Identity()});
  return std::make_shared<VolumeSetCollider>(std::move(volumes));
}

// Every volume's signed distance at p, the least: the union's true distance where p is
// outside all of them.
double unionDistance(const VolumeSetCollider& set, const Vec3& p) {
  double d = kInf;
  for (size_t i = 0; i < set.size(); ++i) d = std::min(d, set.worldVolume(i).nearest(p).distance);
  return d;
}

// A skirt's nodes: a ring of points about the hips.
std::vector<Vec3> hipRing() {
  std::vector<Vec3> ring;
  for (int k = 0; k < 24; ++k) {
    const double a = 2.0 * M_PI * k / 24;
    ring.push_back(Vec3(0.3 * std::cos(a), 0.85 + 0.1 * (k % 3), 0.3 * std::sin(a)));
  }
  return ring;
}
}  // namespace

TEST(BroadPhaseCollider, LeavesOutThePartsFarFromTheGarment) {
  const auto figure = capsuleFigure();
  BroadPhaseCollider broad(figure);
  EXPECT_EQ(broad.focused(), nullptr);  // nothing followed yet
  broad.follow(hipRing());
  const auto* focused = dynamic_cast<const VolumeSetCollider*>(broad.focused());
  ASSERT_NE(focused, nullptr);
  // The head (0.1 m radius above 1.6 m) is far from a ring at 0.85-1.05 m; the trunk, the
  // legs and the arms' lower ends are near it.
  EXPECT_EQ(focused->size(), figure->size() - 1);
  for (size_t i = 0; i < focused->size(); ++i) EXPECT_NE(focused->part(i), 5);
}

TEST(BroadPhaseCollider, AGarmentAroundEveryPartLeavesNothingOut) {
  BroadPhaseCollider broad(capsuleFigure());
  broad.follow({Vec3(-1, -0.5, -1), Vec3(1, 2.5, 1)});
  EXPECT_EQ(broad.focused(), nullptr);
  EXPECT_EQ(broad.refocusCount(), 1);
}

TEST(BroadPhaseCollider, RefocusesOnlyWhenANodeLeavesTheBox) {
  BroadPhaseCollider broad(capsuleFigure());
  std::vector<Vec3> ring = hipRing();
  broad.follow(ring);
  EXPECT_EQ(broad.refocusCount(), 1);
  for (Vec3& x : ring) x.y() -= 0.5 * BroadPhaseCollider::kDefaultSlack;  // still inside the grown box
  broad.follow(ring);
  EXPECT_EQ(broad.refocusCount(), 1);
  ring[0].y() -= BroadPhaseCollider::kDefaultSlack;  // out of it
  broad.follow(ring);
  EXPECT_EQ(broad.refocusCount(), 2);
  EXPECT_TRUE(broad.region().contains(ring[0]));
}

// Points all about the figure, inside and outside the focus box, deep in volumes, in
// the creases between them: the broad phase answers exactly as the whole body, and its
// lower bounds stay lower bounds.
TEST(BroadPhaseCollider, EveryAnswerIsTheWholeBodys) {
  const auto figure = capsuleFigure();
  BroadPhaseCollider broad(figure);
  broad.follow(hipRing());
  ASSERT_NE(broad.focused(), nullptr);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> x(-0.5, 0.5), y(-0.1, 1.9);
  int touching = 0, focusedAnswers = 0;
  for (int k = 0; k < 20000; ++k) {
    const Vec3 p(x(random), y(random), x(random));
    for (const double clearance : {0.003, 0.02}) {
      Contact whole, answer;
      const bool wholeTouches = figure->contact(p, clearance, kInf, whole);
      ASSERT_EQ(broad.contact(p, clearance, kInf, answer), wholeTouches) << p.transpose();
      if (wholeTouches) {
        ++touching;
        EXPECT_EQ(answer.surfacePoint, whole.surfacePoint) << p.transpose();
        EXPECT_EQ(answer.normal, whole.normal) << p.transpose();
        EXPECT_EQ(answer.distance, whole.distance) << p.transpose();
      } else {
        EXPECT_LE(answer.distance, unionDistance(*figure, p) + 1e-12) << p.transpose();
      }
      focusedAnswers += broad.region().contains(p);
    }
  }
  EXPECT_GT(touching, 2000);
  EXPECT_GT(focusedAnswers, 2000);
}

TEST(BroadPhaseCollider, ACompositeBodyIsFocusedPartByPart) {
  auto figure = capsuleFigure();
  auto floor = std::make_shared<PlaneCollider>(Vec3::Zero(), Vec3::UnitY());
  auto body = std::make_shared<CompositeCollider>(std::vector<std::shared_ptr<const Collider>>{figure, floor});
  BroadPhaseCollider broad(body);
  broad.follow(hipRing());
  const auto* focused = dynamic_cast<const CompositeCollider*>(broad.focused());
  ASSERT_NE(focused, nullptr);
  ASSERT_EQ(focused->parts().size(), 2u);
  EXPECT_EQ(dynamic_cast<const VolumeSetCollider&>(*focused->parts()[0]).size(), figure->size() - 1);
  EXPECT_EQ(focused->parts()[1], floor);  // a plane has no parts to leave out
}

TEST(BroadPhaseCollider, RefusesANullBodyAndNonPositiveDistances) {
  EXPECT_THROW(BroadPhaseCollider(nullptr), std::invalid_argument);
  EXPECT_THROW(BroadPhaseCollider(capsuleFigure(), 0.0), std::invalid_argument);
  EXPECT_THROW(BroadPhaseCollider(capsuleFigure(), 0.05, -1.0), std::invalid_argument);
}

// A skirt-like tube dropped round the figure's hips: the drape is bit for bit the same
// with the broad phase and without, on the paper's explicit path and the implicit one.
TEST(BroadPhaseCollider, ADrapeIsTheSameWithItAndWithout) {
  const auto figure = capsuleFigure();
  TriangleMesh tube = meshes::grid(24, 6, 2.0 * M_PI, 0.3);
  for (Vec3& v : tube.vertices) v = Vec3(0.24 * std::cos(v.x()), 1.1 + v.y(), 0.24 * std::sin(v.x()));
  for (const Integrator integrator : {Integrator::Heun, Integrator::Implicit}) {
    ClothParameters p;
    p.integrator = integrator;
    p.timeStep = integrator == Integrator::Heun ? 1.5e-4 : 0.01;
    p.maxTime = integrator == Integrator::Heun ? 0.05 : 0.3;
    ClothParameters off = p;
    off.broadPhase = false;
    ClothSolver with(tube, p, figure), without(tube, off, figure), free(tube, p, nullptr);
    with.run();
    without.run();
    free.run();
    EXPECT_NE(with.positions(), free.positions()) << "the figure never touched the tube";
    ASSERT_NE(with.broadPhase(), nullptr);
    EXPECT_NE(with.broadPhase()->focused(), nullptr) << integratorName(integrator);
    EXPECT_EQ(without.broadPhase(), nullptr);
    EXPECT_EQ(with.positions(), without.positions()) << integratorName(integrator);
    EXPECT_EQ(with.velocities(), without.velocities()) << integratorName(integrator);
  }
}

}  // namespace test_BroadPhaseCollider
