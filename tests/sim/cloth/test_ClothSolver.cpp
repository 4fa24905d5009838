// The solver: analytic free fall, a hanging strip that comes to rest, repeatable runs,
// collisions that keep cloth outside a body, and failures that are reported.
#include <gtest/gtest.h>

#include "sim/cloth/ClothSolver.h"
#include "sim/collision/MeshCollider.h"
#include "support/TestMeshes.h"

using namespace figment;

namespace {
ClothParameters vacuum() {
  ClothParameters p;
  p.airResistance = 0.0;
  p.strainRateDamping = 0.0;
  return p;
}

TriangleMesh hangingStrip() {  // 5 cm x 50 cm, in the x-y plane, top edge at y = 0
  return meshes::grid(2, 20, 0.05, 0.5);
}
}  // namespace

TEST(ClothSolver, FreeFallFollowsHalfGTSquared) {
  // Heun integrates constant acceleration exactly; a rigidly falling sheet has no
  // elastic or bending force, so every node falls g t^2 / 2.
  ClothParameters p = vacuum();
  p.timeStep = 1e-4;
  p.maxTime = 0.5;
  p.rest.window = 1.0;  // never at rest while falling
  const TriangleMesh sheet = meshes::grid(3, 3, 0.2, 0.2);
  ClothSolver solver(sheet, p, nullptr);
  const DrapeResult result = solver.run();
  EXPECT_EQ(result.iterations, 5000);
  EXPECT_FALSE(result.atRest);
  const double t = result.simulatedTime;
  ASSERT_NEAR(t, 0.5, 1e-12);
  for (size_t i = 0; i < sheet.vertices.size(); ++i) {
    const Vec3 expected = sheet.vertices[i] + 0.5 * p.gravity * t * t;
    EXPECT_LT((solver.positions()[i] - expected).norm(), 1e-9) << "node " << i;
  }
}

TEST(ClothSolver, PinnedStripHangsAndComesToRest) {
  ClothParameters p;
  p.maxTime = 8.0;
  const TriangleMesh strip = hangingStrip();
  ClothSolver solver(strip, p, nullptr);
  for (int i = 0; i <= 2; ++i) solver.pin(i);  // the top row
  const DrapeResult result = solver.run();
  EXPECT_TRUE(result.atRest);
  EXPECT_LT(result.simulatedTime, p.maxTime);
  // Pins hold; the bottom hangs straight below them, slightly stretched by the weight.
  for (int i = 0; i <= 2; ++i) EXPECT_EQ(solver.positions()[i], strip.vertices[i]);
  const Vec3 bottom = solver.positions()[strip.vertices.size() - 2];
  EXPECT_NEAR(bottom.x(), 0.025, 1e-3);
  EXPECT_LT(bottom.y(), -0.5);
  EXPECT_GT(bottom.y(), -0.51);
  EXPECT_LT(solver.maxSpeed(), p.rest.speedThreshold);
}

TEST(ClothSolver, RunsRepeatExactly) {
  ClothParameters p;
  p.maxTime = 0.3;
  auto body = std::make_shared<MeshCollider>(meshes::sphere(0.15));
  const TriangleMesh sheet = meshes::grid(12, 12, 0.4, 0.4, Vec3(-0.2, 0.2, 0.2), Vec3::UnitX(), -Vec3::UnitZ());
  ClothSolver first(sheet, p, body), second(sheet, p, body);
  first.run();
  second.run();
  EXPECT_EQ(first.positions(), second.positions());
  EXPECT_EQ(first.velocities(), second.velocities());
}

TEST(ClothSolver, ClothDrapedOverABallStaysOutsideIt) {
  ClothParameters p;
  p.maxTime = 1.5;
  const double radius = 0.15;
  auto body = std::make_shared<MeshCollider>(meshes::sphere(radius, 48, 24));
  // A sheet placed just above the ball, falling onto it.
  const TriangleMesh sheet =
      meshes::grid(16, 16, 0.5, 0.5, Vec3(-0.25, radius + 0.02, 0.25), Vec3::UnitX(), -Vec3::UnitZ());
  ClothSolver solver(sheet, p, body);
  solver.run();
  const double inf = std::numeric_limits<double>::infinity();
  double highest = -inf;
  for (const Vec3& x : solver.positions()) {
    Contact contact;
    body->contact(x, 0.0, inf, contact);
    EXPECT_GT(contact.distance, -1e-4) << x.transpose();
    highest = std::max(highest, x.y());
  }
  // The ball holds the middle of the sheet up; the corners fall past it.
  EXPECT_NEAR(highest, radius + p.clearance, 0.01);
  EXPECT_LT(solver.positions()[0].y(), 0.0);
}

namespace {
// The same body, but it never tells the solver how far away a node is, so the solver
// must query every node on every step.
class AlwaysQueriedBody : public Collider {
 public:
  explicit AlwaysQueriedBody(std::shared_ptr<const Collider> body) : body_(std::move(body)) {}
  bool contact(const Vec3& p, double clearance, double searchRadius, Contact& out) const override {
    ++queries;
    const bool touching = body_->contact(p, clearance, searchRadius, out);
    if (!touching) out.distance = 0.0;
    return touching;
  }
  mutable long queries = 0;

 private:
  std::shared_ptr<const Collider> body_;
};

}  // namespace

TEST(ClothSolver, SkippingFarNodesChangesNothing) {
  // Nodes whose last known distance to the body exceeds what they moved since are not
  // queried; that must give exactly the result of querying every node every step.
  ClothParameters p;
  p.maxTime = 0.4;
  auto ball = std::make_shared<MeshCollider>(meshes::sphere(0.15, 48, 24));
  const TriangleMesh sheet = meshes::grid(16, 16, 0.5, 0.5, Vec3(-0.25, 0.2, 0.25), Vec3::UnitX(), -Vec3::UnitZ());
  auto everyStep = std::make_shared<AlwaysQueriedBody>(ball);
  ClothSolver skipping(sheet, p, ball), querying(sheet, p, everyStep);
  skipping.run();
  querying.run();
  EXPECT_EQ(skipping.positions(), querying.positions());
  EXPECT_EQ(skipping.velocities(), querying.velocities());
  EXPECT_EQ(everyStep->queries, static_cast<long>(sheet.vertices.size()) * querying.iterations());
}

TEST(ClothSolver, RejectsBadParametersNamingTheField) {
  const TriangleMesh sheet = meshes::grid(2, 2, 0.1, 0.1);
  ClothParameters p;
  p.material.thickness = -0.001;
  try {
    ClothSolver solver(sheet, p, nullptr);
    FAIL() << "no error";
  } catch (const std::invalid_argument& error) {
    EXPECT_STREQ(error.what(), "thickness = -0.001 must be > 0");
  }
  p = ClothParameters();
  p.material.poissonRatio = 0.5;
  EXPECT_THROW(ClothSolver(sheet, p, nullptr), std::invalid_argument);
  p = ClothParameters();
  p.timeStep = 0.0;
  EXPECT_THROW(ClothSolver(sheet, p, nullptr), std::invalid_argument);
  // Checked before anything reads the triangles: the solver's edge lengths read vertex 99
  // first, past the vertices (a crash now and then; valgrind: invalid reads).
  TriangleMesh broken = sheet;
  broken.triangles[0][1] = 99;
  try {
    ClothSolver solver(broken, ClothParameters(), nullptr);
    FAIL() << "no error";
  } catch (const std::invalid_argument& error) {
    EXPECT_STREQ(error.what(), "coordIndex = 99 is out of range [0, 8]");
  }
}

TEST(ClothSolver, BlowUpIsReportedNotHidden) {
  // Stiff cloth and a time step far beyond the explicit limit: the run must stop with
  // an error that names the step, the time step and the method.
  ClothParameters p;
  p.material.youngsModulus = 1e9;
  p.strainRateDamping = 0.0;
  p.timeStep = 5e-3;
  p.maxTime = 5.0;
  TriangleMesh strip = hangingStrip();
  ClothSolver solver(strip, p, nullptr);
  for (int i = 0; i <= 2; ++i) solver.pin(i);
  try {
    solver.run();
    FAIL() << "no error";
  } catch (const SimulationError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("at step "), std::string::npos) << message;
    EXPECT_NE(message.find("timeStep = 0.005"), std::string::npos) << message;
    EXPECT_NE(message.find("Heun"), std::string::npos) << message;
  }
}
