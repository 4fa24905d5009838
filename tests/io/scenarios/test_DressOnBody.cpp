// The default dress on the default body (human.zae): the garment figment-make-dress writes
// to scenes/dress.obj. It must start outside the body everywhere, be one consistently wound
// piece, and carry its straps over the shoulders.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <optional>

#include "io/MeshImport.h"
#include "sim/collision/TriangleBvh.h"
#include "sim/garment/StrapDress.h"
#include "support/DefaultBody.h"
#include "support/DressChecks.h"
#include "support/MeshChecks.h"

using namespace figment;

namespace {

class DressOnBody : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (const TriangleMesh* body = test::defaultBodyWithoutEyes()) dress_.emplace(makeStrapDress(*body));
  }
  void SetUp() override {
    if (!dress_) GTEST_SKIP() << "human.zae (assimp-testmodels) is not installed";
  }
  static const TriangleMesh& body() { return *test::defaultBodyWithoutEyes(); }
  static const StrapDress& dress() { return *dress_; }

 private:
  static inline std::optional<StrapDress> dress_;
};

}  // namespace

// Measured on the body: armpits at ~1.22 m, the neck at ~1.46 m; the top 3 cm under the
// armpits, the hem at 0.3 of 1.66 m.
TEST_F(DressOnBody, EdgesFollowTheLandmarks) {
  EXPECT_NEAR(dress().armpitHeight, 1.22, 0.02);
  EXPECT_NEAR(dress().neckHeight, 1.46, 0.03);
  EXPECT_NEAR(dress().topHeight, dress().armpitHeight - 0.03, 1e-12);
  EXPECT_NEAR(dress().hemHeight, 0.498, 0.01);
}

// The neckline: the top edge between the straps, front and back, is necklineRise (8 cm) above
// its height under the arms, over the bust (apex ~1.21 m) by enough to stay above it after the
// drape lowers the dress (~3 cm); beyond the straps' centre lines plus the fade it is not raised.
TEST_F(DressOnBody, NecklineRisesOverTheBust) {
  const StrapDressOptions defaults;
  EXPECT_NEAR(dress().necklineHeight, dress().topHeight + defaults.necklineRise, 1e-12);
  EXPECT_GE(dress().necklineHeight, 1.26);
  int raised[2] = {0, 0}, underArms = 0;
  for (const Vec3& v : checks::tubeTopEdge(dress())) {
    EXPECT_GE(v.y(), dress().topHeight - 1e-12) << v.transpose();
    EXPECT_LE(v.y(), dress().necklineHeight + 1e-12) << v.transpose();
    if (std::abs(v.x()) < 0.09) {
      EXPECT_NEAR(v.y(), dress().necklineHeight, 1e-12) << v.transpose();
      ++raised[v.z() > 0];
    }
    if (std::abs(v.x()) >= defaults.strapOffset + defaults.necklineFade) {
      EXPECT_EQ(v.y(), dress().topHeight) << v.transpose();
      ++underArms;
    }
  }
  EXPECT_GE(raised[0], 5);
  EXPECT_GE(raised[1], 5);
  EXPECT_GE(underArms, 10);
}

// The solver's stable time step scales with the shortest edge: none under 1.5 cm (half the
// strap's width), less a rounding margin.
TEST_F(DressOnBody, NoShortEdges) {
  double shortest = 1e9;
  for (const Triangle& t : dress().mesh.triangles)
    for (int k = 0; k < 3; ++k)
      shortest = std::min(shortest, (dress().mesh.vertices[t[k]] - dress().mesh.vertices[t[(k + 1) % 3]]).norm());
  EXPECT_GE(shortest, 0.0149);
}

TEST_F(DressOnBody, AboutFifteenHundredTriangles) {
  EXPECT_GE(dress().mesh.triangles.size(), 1400u);
  EXPECT_LE(dress().mesh.triangles.size(), 1650u);
}

TEST_F(DressOnBody, OneConsistentlyWoundPieceWithABoundary) {
  EXPECT_EQ(checks::connectedComponents(dress().mesh), 1);
  EXPECT_EQ(checks::mostTrianglesOnAnEdge(dress().mesh), 2);
  EXPECT_TRUE(checks::consistentlyOriented(dress().mesh));
}

// Normals point away from the body: from the body's vertical axis for the tube, from the top
// edge's height on that axis (inside the shoulders) for the straps.
TEST_F(DressOnBody, NormalsPointAwayFromTheBody) {
  double axisZ = 0;
  int counted = 0;
  for (const Vec3& v : body().vertices)
    if (v.y() > dress().hemHeight && v.y() < dress().topHeight && std::abs(v.x()) < 0.2) axisZ += v.z(), ++counted;
  axisZ /= counted;
  int tube = 0, tubeOutward = 0, strap = 0, strapOutward = 0;
  for (size_t i = 0; i < dress().mesh.triangles.size(); ++i) {
    const Triangle& t = dress().mesh.triangles[i];
    const Vec3 c = checks::centroidOf(dress().mesh, t);
    const bool onStrap = checks::onStrap(dress(), static_cast<int>(i));
    const Vec3 inside(onStrap ? c.x() : 0.0, onStrap ? dress().topHeight : c.y(), axisZ);
    const bool outward = checks::normalOf(dress().mesh, t).dot(c - inside) > 0;
    (onStrap ? strap : tube) += 1;
    (onStrap ? strapOutward : tubeOutward) += outward;
  }
  EXPECT_GE(tubeOutward, 0.98 * tube);
  EXPECT_GE(strapOutward, 0.98 * strap);
}

// Outside the body everywhere, by the clearance (1 cm) less the sampling between the body's
// sections (a few hundredths of a millimetre here).
TEST_F(DressOnBody, EveryVertexStartsOutsideWithClearance) {
  const TriangleBvh bvh(body());
  const double clearance = StrapDressOptions{}.clearance;
  double nearest = 1e9;
  for (const Vec3& v : dress().mesh.vertices) {
    EXPECT_FALSE(checks::insideClosedSurface(body(), v)) << v.transpose();
    nearest = std::min(nearest, std::sqrt(bvh.closest(v).distanceSquared));
  }
  EXPECT_GE(nearest, 0.9 * clearance);
}

// The straps rise over the shoulder tops (y ~1.39 m at |x| 0.1) at the strap offsets.
TEST_F(DressOnBody, StrapsGoOverTheShoulders) {
  int high[2] = {0, 0};
  for (const Vec3& v : dress().mesh.vertices)
    if (v.y() >= 1.35) {
      EXPECT_NEAR(std::abs(v.x()), 0.10, 0.015 + 1e-9) << v.transpose();
      ++high[v.x() > 0];
    }
  EXPECT_GE(high[0], 6);
  EXPECT_GE(high[1], 6);
  EXPECT_GE(boundsOf(dress().mesh.vertices).max.y(), 1.4);
}

TEST_F(DressOnBody, SymmetricInX) {
  const std::vector<Vec3>& vertices = dress().mesh.vertices;
  for (const Vec3& v : vertices) {
    const Vec3 mirrored(-v.x(), v.y(), v.z());
    double nearest = 1e9;
    for (const Vec3& w : vertices) nearest = std::min(nearest, (w - mirrored).norm());
    EXPECT_LT(nearest, 0.01) << v.transpose();
  }
}

TEST_F(DressOnBody, Deterministic) {
  const StrapDress again = makeStrapDress(body());
  EXPECT_EQ(again.mesh.vertices, dress().mesh.vertices);
  EXPECT_EQ(again.mesh.triangles, dress().mesh.triangles);
}

// scenes/dress.obj is figment-make-dress's output for the default body: regenerate it
// (cmake --build <dir> --target figment-dress-obj) when the generator changes.
TEST_F(DressOnBody, CommittedSceneFileIsUpToDate) {
  const std::string path = std::string(FIGMENT_SOURCE_DIR) + "/scenes/dress.obj";
  ASSERT_TRUE(std::filesystem::exists(path)) << path;
  const TriangleMesh committed = importMesh(path).mesh;
  ASSERT_EQ(committed.vertices.size(), dress().mesh.vertices.size());
  EXPECT_EQ(committed.triangles, dress().mesh.triangles);
  double largest = 0;
  for (size_t i = 0; i < committed.vertices.size(); ++i)
    largest = std::max(largest, (committed.vertices[i] - dress().mesh.vertices[i]).norm());
  EXPECT_LT(largest, 1e-6);
}
