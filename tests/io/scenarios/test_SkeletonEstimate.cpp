// The humanoid skeleton estimated from the default body by cross sections, and the same
// skeleton from that body turned z-up and in centimetres.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "io/MeshImport.h"
#include "sim/body/SkeletonEstimate.h"
#include "sim/volumes/VolumeShaping.h"

using namespace figment;

namespace {

TriangleMesh defaultBody() {
  ImportOptions options;
  options.exclude = {"human-highpolyeyesMesh"};
  return importMesh(findModelFile("human.zae"), options).mesh;
}

bool humanAvailable() {
  return !findModelFile("human.zae").empty();
}

}  // namespace

TEST(SkeletonEstimate, FindsTheDefaultBodysJointsWhereABodyHasThem) {
  if (!humanAvailable()) GTEST_SKIP() << "assimp-testmodels' human.zae is not installed";
  const TriangleMesh body = defaultBody();
  const Skeleton s = estimateSkeleton(body);
  ASSERT_EQ(s.joints.size(), 25u);
  ASSERT_EQ(s.parts.size(), 17u);
  // Heights (m) of a 1.66 m body: head top at the top, hips above the crotch (0.75 m
  // here), knees and ankles at anthropometric heights, shoulders above the armpits.
  EXPECT_NEAR(s["headTop"].position.y(), 1.66, 0.01);
  EXPECT_NEAR(s["hipL"].position.y(), 0.79, 0.05);
  EXPECT_NEAR(s["kneeL"].position.y(), 0.47, 0.01);
  EXPECT_NEAR(s["ankleR"].position.y(), 0.075, 0.01);
  EXPECT_GT(s["shoulderL"].position.y(), 1.22);
  EXPECT_LT(s["shoulderL"].position.y(), 1.40);
  // Left is +x (the body faces +z); the arms hang out to the hands at |x| ~ 0.5 m.
  for (const char* left : {"hipL", "kneeL", "ankleL", "toeL", "shoulderL", "elbowL", "wristL", "fingertipL"})
    EXPECT_GT(s[left].position.x(), 0.03) << left;
  EXPECT_GT(s["fingertipL"].position.x(), 0.45);
  EXPECT_LT(s["fingertipR"].position.x(), -0.45);
  EXPECT_GT(s["toeL"].position.z(), 0.2) << "toes point forward";
  // The spine climbs: pelvis < waist < chest < neck < head.
  EXPECT_LT(s["pelvis"].position.y(), s["waist"].position.y());
  EXPECT_LT(s["waist"].position.y(), s["chest"].position.y());
  EXPECT_LT(s["chest"].position.y(), s["neckBase"].position.y());
  EXPECT_LT(s["neckTop"].position.y(), s["headTop"].position.y());
  // Every part gets vertices; the hands' lie far out, the feet's low.
  const std::vector<int> part = assignParts(s, body.vertices);
  std::vector<int> count(s.parts.size(), 0);
  for (size_t v = 0; v < part.size(); ++v) {
    ++count[part[v]];
    const std::string& name = s.parts[part[v]].name;
    if (name == "handL") {
      EXPECT_GT(body.vertices[v].x(), 0.3);
    }
    if (name == "footR") {
      EXPECT_LT(body.vertices[v].y(), 0.15);
    }
  }
  for (size_t k = 0; k < s.parts.size(); ++k) EXPECT_GT(count[k], 50) << s.parts[k].name;
}

TEST(SkeletonEstimate, FindsTheSameSkeletonZUpInCentimetres) {
  if (!humanAvailable()) GTEST_SKIP() << "assimp-testmodels' human.zae is not installed";
  const TriangleMesh body = defaultBody();
  TriangleMesh turned = body;  // (x, y, z) m, y up -> (x, -z, y) cm, z up
  for (Vec3& v : turned.vertices) v = 100.0 * Vec3(v.x(), -v.z(), v.y());
  const Skeleton a = estimateSkeleton(body), b = estimateSkeleton(turned);
  for (size_t i = 0; i < a.joints.size(); ++i) {
    const Vec3& p = b.joints[i].position;
    const Vec3 back = Vec3(p.x(), p.z(), -p.y()) / 100.0;
    EXPECT_NEAR((back - a.joints[i].position).norm(), 0.0, 0.002) << a.joints[i].name;
  }
  const std::vector<int> pa = assignParts(a, body.vertices), pb = assignParts(b, turned.vertices);
  int same = 0;
  for (size_t v = 0; v < pa.size(); ++v) same += pa[v] == pb[v];
  EXPECT_GT(same, 0.995 * pa.size());
}

TEST(SkeletonEstimate, ABoxIsNotAHumanoid) {
  TriangleMesh box;
  for (int i = 0; i < 200; ++i) box.vertices.push_back(Vec3(i % 5, i / 5 % 8, i / 40));
  EXPECT_THROW(estimateSkeleton(box), std::invalid_argument);
}

TEST(VolumeShaping, EncloseEveryPartOfTheDefaultBodyAndNameIt) {
  // shapeCapsules and shapeRadialVolumes (sim/volumes/VolumeShaping.h): every part of the skeleton
  // gets volumes carrying its name, and every vertex of a part lies in one of them.
  if (!humanAvailable()) GTEST_SKIP() << "assimp-testmodels' human.zae is not installed";
  const TriangleMesh body = defaultBody();
  const Skeleton skeleton = estimateSkeleton(body);
  const std::vector<PartMesh> parts = splitIntoParts(body, skeleton);
  for (const auto& volumes : {shapeCapsules(body, skeleton), shapeRadialVolumes(body, skeleton)}) {
    std::set<std::string> named;
    for (const CollisionVolumeParameters& v : volumes) named.insert(v.part);
    for (const BodyPart& part : skeleton.parts) EXPECT_TRUE(named.count(part.name)) << part.name;
    for (const PartMesh& part : parts) {
      int outside = 0;
      for (const Vec3& p : part.mesh.vertices) {
        bool inside = false;
        for (const CollisionVolumeParameters& v : volumes)
          if (!inside && v.part == part.name) inside = signedDistance(v, p) <= 1e-9;
        outside += !inside;
      }
      EXPECT_EQ(outside, 0) << part.name;
    }
  }
}
