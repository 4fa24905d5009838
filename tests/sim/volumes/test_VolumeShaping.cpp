// A whole body's collision volumes (sim/volumes/VolumeShaping.h) on a tiny literal body: one bent
// part (an L of two tubes, which one capsule cannot fit) and a straight one. Each
// volume carries its part's name, every part gets one, and the part's vertices are all
// inside its volumes (§3.3: forced enclosure).
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "sim/collision/Capsule.h"
#include "sim/volumes/VolumeShaping.h"
#include "support/TestMeshes.h"

using namespace figment;

namespace {

// A closed tube of radius r from a to b (`slices` around, `rings` along, flat-capped).
void addTube(TriangleMesh& mesh, const Vec3& a, const Vec3& b, double r, int slices = 24, int rings = 12) {
  const Vec3 axis = (b - a).normalized(), u = axis.unitOrthogonal(), v = axis.cross(u);
  const int first = static_cast<int>(mesh.vertices.size());
  for (int i = 0; i <= rings; ++i)
    for (int j = 0; j < slices; ++j) {
      const double angle = 2 * M_PI * j / slices;
      mesh.vertices.push_back(a + (b - a) * i / rings + r * (std::cos(angle) * u + std::sin(angle) * v));
    }
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < slices; ++j) {
      const int p = first + i * slices + j, q = first + i * slices + (j + 1) % slices;
      mesh.triangles.push_back({p, q, p + slices});
      mesh.triangles.push_back({q, q + slices, p + slices});
    }
  for (int end = 0; end < 2; ++end) {  // fans to the end centres
    const int centre = static_cast<int>(mesh.vertices.size());
    mesh.vertices.push_back(end ? b : a);
    for (int j = 0; j < slices; ++j) {
      const int ring = first + end * rings * slices;
      const int p = ring + j, q = ring + (j + 1) % slices;
      mesh.triangles.push_back(end ? Triangle{centre, p, q} : Triangle{centre, q, p});
    }
  }
}

// Joints: 0-1 the straight part "shin", 2-3 the bent part "foot" (its bone along the
// long leg of the L).
Skeleton twoParts() {
  Skeleton s;
  s.joints = {{"knee", -1, Vec3(0, 0.5, 0)},
              {"ankle", 0, Vec3(0, 0.12, 0)},
              {"heel", 1, Vec3(0, 0.05, 0)},
              {"toe", 2, Vec3(0, 0.05, 0.3)}};
  s.parts = {{"shin", 0, 1}, {"foot", 2, 3}};
  return s;
}

TriangleMesh twoPartBody() {
  TriangleMesh body;
  addTube(body, Vec3(0, 0.5, 0), Vec3(0, 0.15, 0), 0.05);           // the shin
  addTube(body, Vec3(0, 0.12, -0.02), Vec3(0, 0.03, -0.02), 0.04);  // the foot: heel ...
  addTube(body, Vec3(0, 0.03, -0.04), Vec3(0, 0.03, 0.3), 0.03);    // ... and sole
  return body;
}

void expectEnclosedAndNamed(const std::vector<CollisionVolumeParameters>& volumes, const TriangleMesh& body,
                            const Skeleton& skeleton) {
  std::set<std::string> named;
  for (const CollisionVolumeParameters& v : volumes) named.insert(v.part);
  for (const BodyPart& part : skeleton.parts) EXPECT_TRUE(named.count(part.name)) << part.name;
  const std::vector<PartMesh> parts = splitIntoParts(body, skeleton);
  for (const PartMesh& part : parts)
    for (const Vec3& p : part.mesh.vertices) {
      bool inside = false;
      for (const CollisionVolumeParameters& v : volumes)
        if (v.part == part.name) inside |= signedDistance(v, p) <= 1e-9;
      EXPECT_TRUE(inside) << part.name << " " << p.transpose();
    }
}

}  // namespace

TEST(VolumeShaping, CapsulesEncloseEveryPartAndCarryItsName) {
  const TriangleMesh body = twoPartBody();
  const Skeleton skeleton = twoParts();
  const std::vector<CollisionVolumeParameters> capsules = shapeCapsules(body, skeleton);
  for (const CollisionVolumeParameters& v : capsules) EXPECT_EQ(v.kind, CollisionVolumeParameters::Kind::Capsule);
  expectEnclosedAndNamed(capsules, body, skeleton);
}

TEST(VolumeShaping, TheBentPartIsSplitIntoSeveralCapsules) {
  // One capsule round an L stands far off it; two (heel, sole) follow it.
  const std::vector<CollisionVolumeParameters> capsules = shapeCapsules(twoPartBody(), twoParts());
  int foot = 0;
  for (const CollisionVolumeParameters& v : capsules) foot += v.part == "foot";
  EXPECT_GE(foot, 2);
}

TEST(VolumeShaping, RadialVolumesEncloseEveryPartAndCarryItsName) {
  const TriangleMesh body = twoPartBody();
  const Skeleton skeleton = twoParts();
  const std::vector<CollisionVolumeParameters> volumes = shapeRadialVolumes(body, skeleton);
  expectEnclosedAndNamed(volumes, body, skeleton);
  // The straight tube is what a radial volume suits: no fallback there.
  for (const CollisionVolumeParameters& v : volumes) {
    if (v.part == "shin") {
      EXPECT_EQ(v.kind, CollisionVolumeParameters::Kind::Radial);
    }
  }
}

TEST(VolumeShaping, TheSameSeedRepeatsTheVolumes) {
  const TriangleMesh body = twoPartBody();
  const std::vector<CollisionVolumeParameters> a = shapeCapsules(body, twoParts()), b = shapeCapsules(body, twoParts());
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].capsule.values(), b[i].capsule.values());
}

TEST(VolumeShaping, SaysWhichPartItIsShapingBeforeEach) {
  VolumeShapingOptions options;
  std::vector<std::string> said;
  options.progress = [&](const std::string& part, int index, int count) {
    EXPECT_EQ(index, static_cast<int>(said.size()));
    EXPECT_EQ(count, 2);
    said.push_back(part);
  };
  const Skeleton skeleton = twoParts();
  shapeRadialVolumes(twoPartBody(), skeleton, options);
  ASSERT_EQ(said.size(), 2u);
  EXPECT_EQ(said[0], skeleton.parts[0].name);
  EXPECT_EQ(said[1], skeleton.parts[1].name);
}
