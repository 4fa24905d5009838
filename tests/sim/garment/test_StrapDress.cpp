// The strap dress on a figure built from boxes (Mannequin.h), where distances to the body are
// exact: a connected, consistently wound mesh with a boundary, outside the body everywhere by
// the clearance, its straps over the shoulders. The same dress on the default body is tested
// in tests/io/scenarios/test_DressOnBody.cpp.
#include <gtest/gtest.h>

#include <stdexcept>

#include "sim/garment/StrapDress.h"
#include "support/BoxFigure.h"
#include "support/DressChecks.h"
#include "support/MeshChecks.h"

using namespace figment;

namespace {

const StrapDress& dressOnFigure() {
  static const StrapDress dress = makeStrapDress(mannequin::figure());
  return dress;
}

}  // namespace

TEST(StrapDress, LandmarksAndEdgesFollowTheBody) {
  const StrapDress& dress = dressOnFigure();
  EXPECT_NEAR(dress.armpitHeight, 1.3, 0.002);  // the shoulder bar's underside
  EXPECT_NEAR(dress.topHeight, dress.armpitHeight - 0.03, 1e-12);
  EXPECT_NEAR(dress.necklineHeight, dress.topHeight + StrapDressOptions{}.necklineRise, 1e-12);
  EXPECT_NEAR(dress.hemHeight, 0.30 * 1.75, 1e-12);
  EXPECT_DOUBLE_EQ(dress.strapX[0], -0.10);
  EXPECT_DOUBLE_EQ(dress.strapX[1], 0.10);
  const Bounds bounds = boundsOf(dress.mesh.vertices);
  EXPECT_NEAR(bounds.min.y(), dress.hemHeight, 1e-12);
}

// 40 columns x 18 rows of quads in the tube and 2 x 14 quads on each strap, two triangles each.
TEST(StrapDress, TriangleCount) {
  const StrapDress& dress = dressOnFigure();
  EXPECT_EQ(dress.mesh.triangles.size(), 2u * (40 * 18 + 2 * 2 * 14));
  EXPECT_EQ(dress.mesh.vertices.size(), 40u * 19 + 2 * 3 * 13);
  EXPECT_EQ(dress.tubeTriangles, 2 * 40 * 18);
}

// The top edge is raised by necklineRise between the straps' centre lines (|x| <= 0.10 on the
// figure's front and back faces), front and back, and not at all beyond them by more than the
// fade (4 cm): under the arms it stays 3 cm below the armpits.
TEST(StrapDress, NecklineRisesBetweenTheStraps) {
  const StrapDress& dress = dressOnFigure();
  const StrapDressOptions defaults;
  const std::vector<Vec3> top = checks::tubeTopEdge(dress);
  ASSERT_EQ(top.size(), 40u);
  int raised[2] = {0, 0};
  for (const Vec3& v : top) {
    EXPECT_GE(v.y(), dress.topHeight - 1e-12) << v.transpose();
    EXPECT_LE(v.y(), dress.necklineHeight + 1e-12) << v.transpose();
    if (std::abs(v.x()) < 0.09) {
      EXPECT_NEAR(v.y(), dress.necklineHeight, 1e-12) << v.transpose();
      ++raised[v.z() > 0];
    }
    if (std::abs(v.x()) >= defaults.strapOffset + defaults.necklineFade) {
      EXPECT_EQ(v.y(), dress.topHeight) << v.transpose();
    }
  }
  EXPECT_GE(raised[0], 3);  // back
  EXPECT_GE(raised[1], 3);  // front
}

// No rise: a flat top edge, and the straps start on it.
TEST(StrapDress, FlatTopWithoutNeckline) {
  StrapDressOptions options;
  options.necklineRise = 0;
  const StrapDress dress = makeStrapDress(mannequin::figure(), options);
  EXPECT_DOUBLE_EQ(dress.necklineHeight, dress.topHeight);
  for (const Vec3& v : checks::tubeTopEdge(dress)) EXPECT_EQ(v.y(), dress.topHeight) << v.transpose();
  double lowest = 1e9;
  for (const Vec3& v : dress.mesh.vertices) lowest = std::min(lowest, v.y());
  EXPECT_NEAR(lowest, dress.hemHeight, 1e-12);
}

TEST(StrapDress, OneConnectedManifoldWithABoundary) {
  const TriangleMesh& mesh = dressOnFigure().mesh;
  EXPECT_EQ(checks::connectedComponents(mesh), 1);
  EXPECT_EQ(checks::mostTrianglesOnAnEdge(mesh), 2);
  EXPECT_FALSE(checks::everyEdgeSharedByTwo(mesh));  // open at the top, hem and strap sides
  EXPECT_TRUE(checks::consistentlyOriented(mesh));
}

// Normals point away from the body: on the tube away from the vertical axis, on the straps
// away from the shoulder under them.
TEST(StrapDress, NormalsPointAwayFromTheBody) {
  const StrapDress& dress = dressOnFigure();
  const TriangleMesh& mesh = dress.mesh;
  int outward = 0;
  for (size_t i = 0; i < mesh.triangles.size(); ++i) {
    const Triangle& t = mesh.triangles[i];
    const Vec3 c = checks::centroidOf(mesh, t);
    const Vec3 inside =
        checks::onStrap(dress, static_cast<int>(i)) ? Vec3(c.x(), dress.topHeight, 0.0) : Vec3(0.0, c.y(), 0.0);
    if (checks::normalOf(mesh, t).dot(c - inside) > 0) ++outward;
  }
  EXPECT_EQ(outward, static_cast<int>(mesh.triangles.size()));
}

TEST(StrapDress, EveryVertexClearsTheBody) {
  const StrapDress& dress = dressOnFigure();
  const double clearance = StrapDressOptions{}.clearance;
  for (const Vec3& v : dress.mesh.vertices)
    EXPECT_GE(mannequin::distanceToFigure(v), clearance - 1e-6) << v.transpose();
}

// The straps go over the shoulders (top at 1.45 m) at the strap offsets, below the head.
TEST(StrapDress, StrapsCrossTheShoulders) {
  const StrapDress& dress = dressOnFigure();
  int overShoulder[2] = {0, 0};
  for (const Vec3& v : dress.mesh.vertices) {
    EXPECT_LT(v.y(), 1.5);
    if (v.y() > 1.45 && std::abs(v.z()) < 0.08) {
      EXPECT_NEAR(std::abs(v.x()), 0.10, 0.015 + 1e-9);
      ++overShoulder[v.x() > 0];
    }
  }
  EXPECT_GE(overShoulder[0], 3);
  EXPECT_GE(overShoulder[1], 3);
}

TEST(StrapDress, SymmetricInX) {
  const std::vector<Vec3>& vertices = dressOnFigure().mesh.vertices;
  for (const Vec3& v : vertices) {
    const Vec3 mirrored(-v.x(), v.y(), v.z());
    double nearest = 1e9;
    for (const Vec3& w : vertices) nearest = std::min(nearest, (w - mirrored).norm());
    EXPECT_LT(nearest, 1e-6) << v.transpose();
  }
}

TEST(StrapDress, Deterministic) {
  const StrapDress again = makeStrapDress(mannequin::figure());
  EXPECT_EQ(again.mesh.vertices, dressOnFigure().mesh.vertices);
  EXPECT_EQ(again.mesh.triangles, dressOnFigure().mesh.triangles);
}

// Vertices come in the order the triangles first use them (the order an OBJ file lists them).
TEST(StrapDress, VerticesNumberedByFirstUse) {
  int next = 0;
  for (const Triangle& t : dressOnFigure().mesh.triangles)
    for (int v : t) {
      EXPECT_LE(v, next);
      if (v == next) ++next;
    }
  EXPECT_EQ(next, static_cast<int>(dressOnFigure().mesh.vertices.size()));
}

TEST(StrapDress, OptionsShapeTheDress) {
  StrapDressOptions options;
  options.rows = 10;
  options.columns = 32;
  options.strapSegments = 8;
  options.topHeight = 1.2;
  options.hemHeight = 0.7;
  const StrapDress dress = makeStrapDress(mannequin::figure(), options);
  EXPECT_EQ(dress.mesh.triangles.size(), 2u * (32 * 10 + 2 * 2 * 8));
  const Bounds bounds = boundsOf(dress.mesh.vertices);
  EXPECT_NEAR(bounds.min.y(), 0.7, 1e-12);
  EXPECT_DOUBLE_EQ(dress.topHeight, 1.2);
}

TEST(StrapDress, RejectsBadOptions) {
  const TriangleMesh figure = mannequin::figure();
  auto withOption = [&](auto change) {
    StrapDressOptions options;
    change(options);
    return options;
  };
  EXPECT_THROW(makeStrapDress(figure, withOption([](auto& o) { o.clearance = 0; })), std::invalid_argument);
  EXPECT_THROW(makeStrapDress(figure, withOption([](auto& o) { o.rows = 1; })), std::invalid_argument);
  EXPECT_THROW(makeStrapDress(figure, withOption([](auto& o) { o.strapOffset = 0.01; })), std::invalid_argument);
  EXPECT_THROW(makeStrapDress(figure, withOption([](auto& o) { o.strapOffset = 0.4; })), std::invalid_argument);
  EXPECT_THROW(makeStrapDress(figure, withOption([](auto& o) { o.hemHeight = 1.5; })), std::invalid_argument);
  EXPECT_THROW(makeStrapDress(figure, withOption([](auto& o) { o.necklineRise = -0.01; })), std::invalid_argument);
  EXPECT_THROW(makeStrapDress(figure, withOption([](auto& o) { o.necklineFade = 0; })), std::invalid_argument);
  try {
    makeStrapDress(figure, withOption([](auto& o) { o.clearance = -0.01; }));
    FAIL() << "no exception";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("clearance"), std::string::npos) << error.what();
  }
}

TEST(StrapDress, ArmlessBodyIsRejected) {
  EXPECT_THROW(makeStrapDress(mannequin::boxMesh({Vec3(-0.2, 0, -0.1), Vec3(0.2, 1.7, 0.1)})), std::invalid_argument);
}
