// The flared skirt on the default body (human.zae): the garment figment-make-skirt writes to
// scenes/skirt.obj. An open cone of about 1,600 triangles and 0.7 m^2, wound outward, its
// waistband 5 mm outside the natural waist, every vertex outside the body.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <optional>

#include "io/MeshImport.h"
#include "sim/collision/TriangleBvh.h"
#include "sim/garment/FlaredSkirt.h"
#include "support/DefaultBody.h"
#include "support/MeshChecks.h"

using namespace figment;

namespace {

class SkirtOnBody : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (const TriangleMesh* body = test::defaultBodyWithoutEyes()) skirt_.emplace(makeFlaredSkirt(*body));
  }
  void SetUp() override {
    if (!skirt_) GTEST_SKIP() << "human.zae (assimp-testmodels) is not installed";
  }
  static const TriangleMesh& body() { return *test::defaultBodyWithoutEyes(); }
  static const FlaredSkirt& skirt() { return *skirt_; }

 private:
  static inline std::optional<FlaredSkirt> skirt_;
};

}  // namespace

TEST_F(SkirtOnBody, SixteenHundredTrianglesAndSevenTenthsOfASquareMetre) {
  EXPECT_EQ(skirt().mesh.triangles.size(), 1600u);
  EXPECT_NEAR(skirt().area, 0.7, 0.05);
  // The natural waist of a 1.7 m body, about 0.62 of stature up (Drillis & Contini 1966).
  EXPECT_GT(skirt().waistHeight, 0.98);
  EXPECT_LT(skirt().waistHeight, 1.12);
}

TEST_F(SkirtOnBody, OneOpenConeWoundOutward) {
  const TriangleMesh& mesh = skirt().mesh;
  EXPECT_EQ(checks::connectedComponents(mesh), 1);
  EXPECT_EQ(checks::mostTrianglesOnAnEdge(mesh), 2);
  EXPECT_TRUE(checks::consistentlyOriented(mesh));
  int boundary = 0;
  for (const auto& [edge, uses] : checks::edgeUses(mesh)) boundary += uses == 1;
  EXPECT_EQ(boundary, 2 * FlaredSkirtOptions{}.columns) << "the waistband and the hem";
  // Outward: each normal points away from the vertical axis through the waist.
  Vec3 axis = Vec3::Zero();
  for (const Vec3& v : mesh.vertices) axis += v;
  axis /= static_cast<double>(mesh.vertices.size());
  for (const Triangle& t : mesh.triangles) {
    Vec3 radial = checks::centroidOf(mesh, t) - axis;
    radial.y() = 0.0;
    EXPECT_GT(checks::normalOf(mesh, t).normalized().dot(radial.normalized()), 0.5);
  }
}

TEST_F(SkirtOnBody, WaistbandLiesJustOutsideTheNaturalWaist) {
  const TriangleBvh bvh(body());
  const int columns = FlaredSkirtOptions{}.columns;
  double nearest = 1e9;
  int waistband = 0;
  for (const Vec3& v : skirt().mesh.vertices) {
    if (v.y() != skirt().waistHeight) continue;
    ++waistband;
    nearest = std::min(nearest, std::sqrt(bvh.closest(v).distanceSquared));
  }
  EXPECT_EQ(waistband, columns);
  // Where the waist's convex outline touches the skin, the waistband is 5 mm off it.
  EXPECT_NEAR(nearest, FlaredSkirtOptions{}.waistClearance, 0.001);
  EXPECT_GT(skirt().waistbandPerimeter, skirt().waistPerimeter);
}

TEST_F(SkirtOnBody, EveryVertexStartsOutsideTheBody) {
  const TriangleBvh bvh(body());
  double nearest = 1e9;
  for (const Vec3& v : skirt().mesh.vertices) {
    EXPECT_FALSE(checks::insideClosedSurface(body(), v)) << v.transpose();
    nearest = std::min(nearest, std::sqrt(bvh.closest(v).distanceSquared));
  }
  // The clearance holds at the sections; between them the skin bulges a little nearer.
  EXPECT_GE(nearest, 0.8 * FlaredSkirtOptions{}.waistClearance);
}

TEST_F(SkirtOnBody, BadOptionsAreNamed) {
  FlaredSkirtOptions options;
  options.length = -0.1;
  EXPECT_THROW(
      {
        try {
          makeFlaredSkirt(body(), options);
        } catch (const std::invalid_argument& e) {
          EXPECT_NE(std::string(e.what()).find("length = -0.1"), std::string::npos) << e.what();
          throw;
        }
      },
      std::invalid_argument);
}

// scenes/skirt.obj is figment-make-skirt's output for the default body: regenerate it
// (cmake --build <dir> --target figment-skirt-obj) when the generator changes.
TEST_F(SkirtOnBody, CommittedSceneFileIsUpToDate) {
  const std::string path = std::string(FIGMENT_SOURCE_DIR) + "/scenes/skirt.obj";
  ASSERT_TRUE(std::filesystem::exists(path)) << path;
  const TriangleMesh committed = importMesh(path).mesh;
  ASSERT_EQ(committed.vertices.size(), skirt().mesh.vertices.size());
  EXPECT_EQ(committed.triangles, skirt().mesh.triangles);
  double largest = 0;
  for (size_t i = 0; i < committed.vertices.size(); ++i)
    largest = std::max(largest, (committed.vertices[i] - skirt().mesh.vertices[i]).norm());
  EXPECT_LT(largest, 1e-6);
}
