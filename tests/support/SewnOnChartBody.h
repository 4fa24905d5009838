#pragma once
// A GarmentCode pattern sewn and draped on a chart size's body (MakeHuman's, made to the
// chart's stature and girths) as figment-sew does it, and the checks of a sewn
// garment at rest (issue 44): every seam pair merged, no gap over 2 mm, at rest, no edge
// past the tear bound, no node inside the body, and seams that started open. Shared by the
// shipped patterns' test (tests/io/scenarios/test_SewnPatterns.cpp) and the other designs'
// (test_OtherDesigns.cpp).

#include <gtest/gtest.h>

#include <memory>
#include <ostream>
#include <string>

#include "io/PatternFile.h"
#include "sim/cloth/DrapeVerdict.h"
#include "sim/cloth/MaterialPresets.h"
#include "sim/collision/MeshCollider.h"
#include "sim/drape/GarmentDrape.h"
#include "sim/pattern/PatternCutting.h"
#include "sim/pattern/PatternPlacement.h"
#include "support/ChartBodies.h"

namespace figment::test {

// As figment-sew drapes (tools/sew.cpp): cotton, backward Euler from 1/20 s growing to 0.4 s
// while the cloth is quiet, up to 20 s.
inline ClothParameters sewnDrapeParameters() {
  ClothParameters p;
  p.material = *materialPreset("cotton");
  p.integrator = Integrator::Implicit;
  p.timeStep = 0.05;
  p.implicitSolver.maxTimeStep = ImplicitSolverParameters::kShippedMaxTimeStep;
  p.maxTime = 20.0;
  p.friction = 0.5;
  p.clearance = 0.003;
  return p;
}

// A pattern file and the chart size it was made for (the chart's letter code for `sex`); a
// test's name ends in the file's.
struct ChartPattern {
  const char* file;
  Sex sex;
  const char* size;
};

inline void PrintTo(const ChartPattern& p, std::ostream* out) {
  *out << p.file;
}

// A suite of patterns each sewn on its size's chart body: MakeHuman's model and the chart read
// once for the suite; its tests skip when MakeHuman's data is absent.
class ChartBodyPatterns : public ::testing::TestWithParam<ChartPattern> {
 protected:
  static void SetUpTestSuite() { bodies_ = loadChartBodies(); }
  static void TearDownTestSuite() { bodies_.reset(); }
  void SetUp() override {
    if (!bodies_) GTEST_SKIP() << kMakeHumanDataSkip;
  }
  static inline std::unique_ptr<ChartBodies> bodies_;
};

// Reads `file` (a missing or bad file throws, failing the test), places it on the chart body
// of `size` (the chart's letter code for `sex`), sews and drapes it at 2 cm, and checks it.
inline void expectSewsClosedAndRests(const ChartBodies& bodies, const std::string& file, Sex sex, const char* size) {
  const int index = bodies.chart.find(sex, size);
  ASSERT_GE(index, 0) << size;
  const TriangleMesh body = bodies.human->measuredBody(bodies.chart.sizes(sex)[index]).body;
  const SewingPattern pattern = readPatternFile(file);
  const UnsewnGarment cut = cutPattern(placed(pattern, placementOn(body, 0.0)), 0.02);
  auto collider = std::make_shared<MeshCollider>(body);
  DrapeRequest request;
  request.garment = cut.placed;
  request.parameters = sewnDrapeParameters();
  request.body = collider;
  request.sewing = DrapeSewing{cut.flat, cut.seams, {}};
  const GarmentDrape drape = drapeGarment(request);

  ASSERT_TRUE(drape.sewing.has_value());
  EXPECT_EQ(drape.sewing->openPairs, 0);
  EXPECT_LE(drape.sewing->seamGap, 0.002);  // m: the bound on any seam's gap at rest
  EXPECT_TRUE(drape.report.run.atRest);
  EXPECT_LT(drape.report.run.maxStretch, DrapeVerdict::kTearStretch);
  int inside = 0;
  for (const Vec3& x : drape.positions) {
    Contact contact;
    if (collider->contact(x, 0.0, 0.3, contact) && contact.distance < 0.0) ++inside;
  }
  EXPECT_EQ(inside, 0);
  // The control: the panels started apart, so the sewing had seams to close.
  EXPECT_GT(largestSeamGap(cut, cut.placed.vertices), 0.1);
}

}  // namespace figment::test
