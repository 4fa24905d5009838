// Linear blend skinning of the body mesh (sim/body/Skinning.h) on a small T-posed humanoid:
// rigid far from the joints, half and half at a joint, exact at rest.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sim/body/Posing.h"
#include "sim/body/Skinning.h"

using namespace figment;

namespace {
// The skeleton of test_Posing.cpp: y up, floor at 0, arms along +-x at y = 1.45.
Skeleton tPose() {
  return humanoidSkeleton({{0, 1.0, 0},      {0, 1.1, 0},      {0, 1.3, 0},     {0, 1.5, 0},       {0, 1.6, 0},
                           {0, 1.8, 0},      {0.1, 0.95, 0},   {0.1, 0.5, 0},   {0.1, 0.08, 0},    {0.1, 0.0, 0.15},
                           {-0.1, 0.95, 0},  {-0.1, 0.5, 0},   {-0.1, 0.08, 0}, {-0.1, 0.0, 0.15}, {0.2, 1.45, 0},
                           {0.5, 1.45, 0},   {0.75, 1.45, 0},  {0.95, 1.45, 0}, {-0.2, 1.45, 0},   {-0.5, 1.45, 0},
                           {-0.75, 1.45, 0}, {-0.95, 1.45, 0}, {0.05, 1.45, 0}, {-0.05, 1.45, 0},  {0, 0.9, 0}});
}

int part(const Skeleton& s, const std::string& name) {
  for (size_t k = 0; k < s.parts.size(); ++k)
    if (s.parts[k].name == name) return static_cast<int>(k);
  return -1;
}

Pose rotate(const Skeleton& s, const std::string& joint, double angle, const Vec3& axis) {
  Pose pose;
  pose.rotations.resize(s.joints.size(), Eigen::Quaterniond::Identity());
  pose.rotations[s.joint(joint)] = Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis));
  return pose;
}

std::vector<Vec3> bodyCloud(int count) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> x(-1.0, 1.0), y(0.0, 1.85), z(-0.15, 0.2);
  std::vector<Vec3> points;
  for (int i = 0; i < count; ++i) points.emplace_back(x(rng), y(rng), z(rng));
  return points;
}

double weightOf(const SkinWeights& w, size_t vertex, int part) {
  double total = 0.0;
  for (const auto& influence : w.vertices[vertex])
    if (influence.part == part) total += influence.weight;
  return total;
}
}  // namespace

TEST(Skinning, WeightsSumToOne) {
  const Skeleton s = tPose();
  const std::vector<Vec3> cloud = bodyCloud(5000);
  const SkinWeights w = skinWeights(s, cloud);
  ASSERT_EQ(w.vertices.size(), cloud.size());
  int blended = 0;
  for (const auto& influences : w.vertices) {
    double sum = 0.0;
    int used = 0;
    for (const auto& influence : influences) {
      EXPECT_GE(influence.weight, 0.0);
      EXPECT_LE(influence.weight, 1.0);
      sum += influence.weight;
      used += influence.weight > 0.0;
    }
    EXPECT_NEAR(sum, 1.0, 1e-15);
    blended += used > 1;
  }
  EXPECT_GT(blended, 100);
}

TEST(Skinning, IdentityTransformsGiveTheRestPositionsExactly) {
  const Skeleton s = tPose();
  const std::vector<Vec3> cloud = bodyCloud(2000);
  const std::vector<Vec3> posed =
      skin(skinWeights(s, cloud), std::vector<Eigen::Affine3d>(s.parts.size(), Eigen::Affine3d::Identity()), cloud);
  for (size_t v = 0; v < cloud.size(); ++v) EXPECT_EQ(posed[v], cloud[v]);
}

TEST(Skinning, VerticesFarFromJointsFollowTheirPartRigidly) {
  const Skeleton s = tPose();
  // Mid-forearm and mid-upper-arm, 3 cm off the bone: farther than 4 cm from any joint along it.
  const std::vector<Vec3> vertices = {{0.625, 1.48, 0.0}, {0.35, 1.45, 0.03}, {0.62, 1.42, -0.01}};
  const std::vector<int> parts = {part(s, "forearmL"), part(s, "upperArmL"), part(s, "forearmL")};
  const SkinWeights w = skinWeights(s, vertices);
  const std::vector<Eigen::Affine3d> transforms =
      partTransforms(s, rotate(s, "elbowL", 1.0, Vec3(0, 1, 1).normalized()), Sizing{1.1, 1.0, 1.0, 1.0, 1.2});
  const std::vector<Vec3> posed = skin(w, transforms, vertices);
  for (size_t v = 0; v < vertices.size(); ++v) {
    EXPECT_EQ(weightOf(w, v, parts[v]), 1.0);
    EXPECT_LT((posed[v] - transforms[parts[v]] * vertices[v]).norm(), 1e-14);
  }
}

TEST(Skinning, VertexAtAJointMovesByTheAverageOfBothParts) {
  const Skeleton s = tPose();
  const Vec3 v = s["elbowL"].position + Vec3(0, 0.03, 0.01);  // on the elbow's plane across the arm
  const SkinWeights w = skinWeights(s, {v});
  EXPECT_NEAR(weightOf(w, 0, part(s, "upperArmL")), 0.5, 1e-15);
  EXPECT_NEAR(weightOf(w, 0, part(s, "forearmL")), 0.5, 1e-15);
  const std::vector<Eigen::Affine3d> transforms =
      partTransforms(s, rotate(s, "elbowL", M_PI / 2, Vec3::UnitZ()), Sizing{});
  const Vec3 posed = skin(w, transforms, {v})[0];
  const Vec3 average = 0.5 * (transforms[part(s, "upperArmL")] * v + transforms[part(s, "forearmL")] * v);
  EXPECT_LT((posed - average).norm(), 1e-15);
  EXPECT_GT((posed - v).norm(), 0.01);
}

TEST(Skinning, WeightBlendsSmoothlyAcrossTheJoint) {
  const Skeleton s = tPose();
  // Along the arm through the elbow (x = 0.5), 2 cm off the bone.
  std::vector<Vec3> line;
  for (int i = 0; i <= 200; ++i) line.emplace_back(0.42 + 0.16 * i / 200, 1.47, 0.0);
  const SkinWeights w = skinWeights(s, line, 0.04);
  const int forearm = part(s, "forearmL");
  double previous = 0.0;
  for (size_t i = 0; i < line.size(); ++i) {
    const double x = line[i].x() - 0.5, wf = weightOf(w, i, forearm);
    if (x <= -0.04) {
      EXPECT_NEAR(wf, 0.0, 1e-12);
    }
    if (x >= 0.04) {
      EXPECT_NEAR(wf, 1.0, 1e-12);
    }
    EXPECT_GE(wf, previous - 1e-15);         // monotonic
    EXPECT_LE(wf - previous, 0.04 + 1e-12);  // no jump: smoothstep's slope is 1.5 / (2 R) per m
    previous = wf;
  }
}

TEST(Skinning, ThighsBlendIntoTheHipsAndArmsIntoTheTorso) {
  const Skeleton s = tPose();
  // Just below the left hip joint along the thigh, and just outside the left shoulder.
  const SkinWeights w = skinWeights(s, {{0.1, 0.94, 0.05}, {0.21, 1.47, 0.0}});
  EXPECT_GT(weightOf(w, 0, part(s, "hips")), 0.3);
  EXPECT_GT(weightOf(w, 0, part(s, "thighL")), 0.5);
  EXPECT_GT(weightOf(w, 1, part(s, "upperTorso")), 0.3);
}

TEST(Skinning, RejectsBadInput) {
  const Skeleton s = tPose();
  EXPECT_THROW(skinWeights(s, {Vec3::Zero()}, 0.0), std::invalid_argument);
  const SkinWeights w = skinWeights(s, {Vec3::Zero()});
  EXPECT_THROW(skin(w, std::vector<Eigen::Affine3d>(s.parts.size()), {}), std::invalid_argument);
  EXPECT_THROW(skin(w, {}, {Vec3::Zero()}), std::invalid_argument);
}
