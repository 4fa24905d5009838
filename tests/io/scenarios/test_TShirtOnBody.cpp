// The T-shirt on the default body (human.zae): the garment figment-make-tshirt writes to
// scenes/tshirt.obj. One manifold piece of the chosen number of triangles with four
// openings (neck, hem, two sleeves), wound outward, every vertex outside the body.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <set>

#include "io/MeshImport.h"
#include "sim/collision/TriangleBvh.h"
#include "sim/core/BoundaryLoops.h"
#include "sim/garment/TShirt.h"
#include "support/DefaultBody.h"
#include "support/MeshChecks.h"

using namespace figment;

namespace {

class TShirtOnBody : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (const TriangleMesh* body = test::defaultBodyWithoutEyes()) shirt_.emplace(makeTShirt(*body));
  }
  void SetUp() override {
    if (!shirt_) GTEST_SKIP() << "human.zae (assimp-testmodels) is not installed";
  }
  static const TriangleMesh& body() { return *test::defaultBodyWithoutEyes(); }
  static const TShirt& shirt() { return *shirt_; }

 private:
  static inline std::optional<TShirt> shirt_;
};

// The boundary edges, each from one vertex to the next around its loop.
std::map<int, int> boundaryNext(const TriangleMesh& mesh) {
  std::map<std::pair<int, int>, int> use;
  for (const Triangle& t : mesh.triangles)
    for (int e = 0; e < 3; ++e) ++use[std::minmax(t[e], t[(e + 1) % 3])];
  std::map<int, int> next;
  for (const Triangle& t : mesh.triangles)
    for (int e = 0; e < 3; ++e)
      if (use[std::minmax(t[e], t[(e + 1) % 3])] == 1) next[t[e]] = t[(e + 1) % 3];
  return next;
}

}  // namespace

TEST_F(TShirtOnBody, OneManifoldPieceOfTheChosenTriangles) {
  EXPECT_NEAR(static_cast<double>(shirt().mesh.triangles.size()), 1000.0, 1.0);  // a boundary collapse takes 1
  std::map<std::pair<int, int>, int> use;
  for (const Triangle& t : shirt().mesh.triangles)
    for (int e = 0; e < 3; ++e) ++use[std::minmax(t[e], t[(e + 1) % 3])];
  for (const auto& [edge, count] : use) ASSERT_LE(count, 2) << edge.first << "-" << edge.second;
  // One piece, both sides of every inner edge walked oppositely (a garment with a
  // detached sleeve or a flipped panel fails here).
  EXPECT_EQ(figment::checks::connectedComponents(shirt().mesh), 1);
  EXPECT_TRUE(figment::checks::consistentlyOriented(shirt().mesh));
  EXPECT_NEAR(shirt().area, 0.6, 0.1);
}

// The boundary loops, each as its vertices in order.
std::vector<std::vector<int>> openings(const TriangleMesh& mesh) {
  std::map<int, int> next = boundaryNext(mesh);
  std::vector<std::vector<int>> loops;
  std::set<int> seen;
  for (const auto& [start, unused] : next) {
    if (seen.count(start)) continue;
    loops.emplace_back();
    for (int v = start; !seen.count(v); v = next.at(v)) seen.insert(v), loops.back().push_back(v);
  }
  return loops;
}

double meanHeight(const TriangleMesh& mesh, const std::vector<int>& loop) {
  double sum = 0.0;
  for (int v : loop) sum += mesh.vertices[v].y();
  return sum / loop.size();
}

TEST_F(TShirtOnBody, FourOpeningsNeckSleevesAndAStraightLevelHem) {
  std::vector<std::vector<int>> loops = openings(shirt().mesh);
  ASSERT_EQ(loops.size(), 4u);
  std::sort(loops.begin(), loops.end(),
            [](const auto& a, const auto& b) { return meanHeight(shirt().mesh, a) < meanHeight(shirt().mesh, b); });
  // The hem, the lowest, is cut along the hem plane: every vertex of it lies on it.
  for (int v : loops[0]) EXPECT_NEAR(shirt().mesh.vertices[v].y(), shirt().hemHeight, 1e-9);
  EXPECT_GT(meanHeight(shirt().mesh, loops[3]), 1.35);  // the neck the highest
}

// The openings are cut along planes and a sphere, not along the skin's triangles: they turn a
// median 8.9 degrees a vertex (49 when they followed the skin), the hem and the sleeves'
// ends each lie in their plane, and no section is a sliver: the thinnest has 15 % of the
// median's area (14 % when the shirt was the decimated skin alone).
TEST_F(TShirtOnBody, OpeningsReadAsCurvesWithoutSlivers) {
  const TriangleMesh& mesh = shirt().mesh;
  EXPECT_LE(medianBoundaryTurning(mesh.vertices, mesh.triangles), 12.0);
  std::vector<double> areas;
  for (const Triangle& t : mesh.triangles)
    areas.push_back(
        0.5 * (mesh.vertices[t[1]] - mesh.vertices[t[0]]).cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]).norm());
  std::sort(areas.begin(), areas.end());
  EXPECT_GT(areas.front(), 0.1 * areas[areas.size() / 2]);
  // Each sleeve's end: its vertices on one plane, the mean distance from their best plane
  // (least squares) under 0.1 mm.
  std::vector<std::vector<int>> loops = openings(mesh);
  ASSERT_EQ(loops.size(), 4u);
  for (const std::vector<int>& loop : loops) {
    Vec3 centre = Vec3::Zero();
    for (int v : loop) centre += mesh.vertices[v] / static_cast<double>(loop.size());
    Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
    for (int v : loop) scatter += (mesh.vertices[v] - centre) * (mesh.vertices[v] - centre).transpose();
    const double smallest = std::max(0.0, Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(scatter).eigenvalues()(0));
    if (meanHeight(mesh, loop) < 1.3) {
      EXPECT_LT(std::sqrt(smallest / loop.size()), 1e-4) << "a hem or sleeve";
    }
  }
}

TEST_F(TShirtOnBody, WoundOutwardAndEveryVertexOutsideTheBody) {
  const TriangleBvh bvh(body());
  double nearest = 1e9;
  for (const Vec3& v : shirt().mesh.vertices) {
    EXPECT_FALSE(checks::insideClosedSurface(body(), v)) << v.transpose();
    nearest = std::min(nearest, std::sqrt(bvh.closest(v).distanceSquared));
  }
  EXPECT_GE(nearest, 0.3 * TShirtOptions{}.ease);
  // Outward: the normals point away from the nearest skin.
  int outward = 0;
  for (const Triangle& t : shirt().mesh.triangles) {
    const Vec3 &a = shirt().mesh.vertices[t[0]], &b = shirt().mesh.vertices[t[1]], &c = shirt().mesh.vertices[t[2]];
    const Vec3 centre = (a + b + c) / 3.0;
    outward += (b - a).cross(c - a).dot(centre - bvh.closest(centre).point) > 0.0;
  }
  EXPECT_GT(outward, 0.95 * shirt().mesh.triangles.size());
}

// Finer than the skin it is made from: subdivided, then decimated to the count; the same
// shirt (area, hem) in more sections.
TEST_F(TShirtOnBody, MoreTrianglesThanTheSkinHas) {
  TShirtOptions options;
  options.triangles = 3 * shirt().skinTriangles;
  const TShirt fine = makeTShirt(body(), options);
  EXPECT_NEAR(static_cast<double>(fine.mesh.triangles.size()), options.triangles, 1.0);
  EXPECT_NEAR(fine.area, shirt().area, 0.02 * shirt().area);
  EXPECT_LE(checks::mostTrianglesOnAnEdge(fine.mesh), 2);
  EXPECT_EQ(openings(fine.mesh).size(), 4u);
}

// scenes/tshirt.obj is figment-make-tshirt's output for the default body: regenerate it
// (cmake --build <dir> --target figment-tshirt-obj) when the generator changes.
TEST_F(TShirtOnBody, CommittedSceneFileIsUpToDate) {
  const std::string path = std::string(FIGMENT_SOURCE_DIR) + "/scenes/tshirt.obj";
  ASSERT_TRUE(std::filesystem::exists(path)) << path;
  const TriangleMesh committed = importMesh(path).mesh;
  ASSERT_EQ(committed.vertices.size(), shirt().mesh.vertices.size());
  EXPECT_EQ(committed.triangles, shirt().mesh.triangles);
  double largest = 0;
  for (size_t i = 0; i < committed.vertices.size(); ++i)
    largest = std::max(largest, (committed.vertices[i] - shirt().mesh.vertices[i]).norm());
  EXPECT_LT(largest, 1e-6);
}
