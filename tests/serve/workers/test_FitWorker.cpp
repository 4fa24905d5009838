// A worker's made bodies and size drapes: the body the advice judges on is the mesh a
// HumanBody node of the same measurements draws (so a picture shows the advice's drape on
// its own body), and each size's drape is made once: kept in memory, then found in the drape
// cache by another worker, with the same points; a sewn style's size is sewn on the made
// body. Skipped, before anything runs, where the file system has none of MakeHuman's data.

#include <Inventor/SoDB.h>
#include <gtest/gtest.h>

#include "io/DrapeCache.h"
#include "io/GarmentCatalogue.h"
#include "io/MakeHumanFiles.h"
#include "nodes/Init.h"
#include "nodes/body/HumanBody.h"
#include "serve/workers/FitWorker.h"
#include "sim/cloth/DrapeVerdict.h"
#include "sim/pattern/Sewing.h"
#include "support/ShippedCatalogue.h"
#include "support/TempDir.h"

using namespace figment;
using namespace figment::serve;

namespace {

// A body between the chart's sizes, given to the mm as a request gives it.
const BodyMeasures kShopper{1.702, 0.903, 0.741, 0.987};

class FitWorkerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (findMakeHumanData().empty()) GTEST_SKIP() << "MakeHuman's data not found (scripts/setup.sh fetches it)";
    SoDB::init();
    figment::init();
  }
};

}  // namespace

TEST_F(FitWorkerTest, TheMadeBodyIsTheMeshAHumanBodyNodeDraws) {
  FitWorker worker(test::shippedCatalogue().chart());
  const TriangleMesh& made = worker.madeBody(kShopper, Sex::Female);
  auto* node = new HumanBody;  // as the service's scene sets it (serve/scene/OutfitScene.cpp)
  node->ref();
  node->gender = 0.0f;
  node->stature = float(kShopper.stature);
  node->bustGirth = float(kShopper.bust);
  node->waistGirth = float(kShopper.waist);
  node->hipGirth = float(kShopper.hips);
  ASSERT_EQ(size_t(node->point.getNum()), made.vertices.size());
  double largest = 0;
  for (size_t i = 0; i < made.vertices.size(); ++i) {
    const SbVec3f& p = node->point[int(i)];
    largest = std::max(largest, (Vec3(p[0], p[1], p[2]) - made.vertices[i]).norm());
  }
  EXPECT_LT(largest, 1e-6);  // the same mesh, but for the node's float points
  // To the bit where it collides: the worker keeps the node's surface as its made body
  // (FitWorker::keepBody), and a size drape's key digests those vertices.
  EXPECT_EQ(node->collisionSurface().vertices, made.vertices);
  EXPECT_EQ(node->collisionSurface().triangles, made.triangles);
  node->unref();
  // The control: another body is another mesh.
  const TriangleMesh& other = worker.madeBody({1.702, 0.903, 0.741, 1.010}, Sex::Female);
  double moved = 0;
  for (size_t i = 0; i < made.vertices.size(); ++i)
    moved = std::max(moved, (other.vertices[i] - made.vertices[i]).norm());
  EXPECT_GT(moved, 1e-3);
}

TEST_F(FitWorkerTest, ASizeDrapeIsMadeOnceAndFoundAgainInTheDrapeCache) {
  test::TempDir folder;
  const auto cache = std::make_shared<const DrapeCache>(folder.path(), 64u << 20);
  FitWorker first(test::shippedCatalogue().chart());
  first.useCache(cache);
  const GarmentDrape made = first.sizeDrape(kShopper, Sex::Female, "pencil", "M");
  EXPECT_FALSE(made.report.fromCache);
  EXPECT_TRUE(made.report.run.atRest) << made.report.verdict;
  ASSERT_FALSE(made.positions.empty());
  const GarmentDrape again = first.sizeDrape(kShopper, Sex::Female, "pencil", "M");
  EXPECT_TRUE(again.report.fromCache);  // from memory
  EXPECT_EQ(again.positions, made.positions);
  FitWorker second(test::shippedCatalogue().chart());  // another worker, the same cache
  second.useCache(cache);
  const GarmentDrape found = second.sizeDrape(kShopper, Sex::Female, "pencil", "M");
  EXPECT_TRUE(found.report.fromCache);
  EXPECT_EQ(found.positions, made.positions);
  EXPECT_EQ(found.report.run.iterations, made.report.run.iterations);
  // Another size is another drape.
  EXPECT_NE(second.sizeDrape(kShopper, Sex::Female, "pencil", "L").positions, made.positions);
}

TEST_F(FitWorkerTest, ChartBodiesServeEveryStyleAndIntendedFitsAreFoundInTheCache) {
  test::TempDir folder;
  const auto cache = std::make_shared<const DrapeCache>(folder.path(), 64u << 20);
  FitRequest pencil;
  pencil.sex = Sex::Female;
  pencil.style = "pencil";
  pencil.body = kShopper;
  FitWorker first(test::shippedCatalogue().chart());
  first.useCache(cache);
  const FitWorker::Answer advised = first.advise(pencil);
  ASSERT_EQ(advised.status, 200) << advised.body;
  EXPECT_EQ(first.chartBodiesMade(), 3);  // the three candidates' chart bodies
  EXPECT_EQ(first.ownDrapesMade(), 3);    // and each size on its own body
  FitRequest skirt = pencil;
  skirt.style = "skirt";
  ASSERT_EQ(first.advise(skirt).status, 200);
  EXPECT_EQ(first.chartBodiesMade(), 3);  // the same sizes' bodies, for another style
  EXPECT_EQ(first.ownDrapesMade(), 6);    // its own intended fits
  // Another worker (or instance) sharing the cache drapes no intended fit again, and
  // advises the same from them.
  FitWorker second(test::shippedCatalogue().chart());
  second.useCache(cache);
  const FitWorker::Answer again = second.advise(pencil);
  EXPECT_EQ(second.ownDrapesMade(), 0);
  EXPECT_EQ(again.body, advised.body);
}

TEST_F(FitWorkerTest, ASewnStylesSizeIsSewnOnTheMadeBodyClosedAndFoundAgain) {
  const GarmentCatalogue& shop = test::shippedCatalogue();
  // Without the catalogue a worker knows only the generators' styles.
  FitWorker cutOnly(shop.chart());
  EXPECT_FALSE(cutOnly.fits("pencilskirt"));
  EXPECT_THROW(cutOnly.sizeDrape(kShopper, Sex::Female, "pencilskirt", "M"), std::invalid_argument);
  test::TempDir folder;
  const auto cache = std::make_shared<const DrapeCache>(folder.path(), 64u << 20);
  FitWorker first(shop.chart(), &shop);
  first.useCache(cache);
  ASSERT_TRUE(first.fits("pencilskirt"));
  const GarmentDrape sewn = first.sizeDrape(kShopper, Sex::Female, "pencilskirt", "M");
  EXPECT_FALSE(sewn.report.fromCache);
  EXPECT_TRUE((DrapeVerdict{sewn.report.run, sewn.report.maxTime}.clean())) << sewn.report.verdict;
  // One point per panel node, on the triangles the graded garment has (what a picture draws),
  // its rest shape the flat panels.
  const SizeFitter::Graded& graded = first.graded("pencilskirt", Sex::Female, "M");
  ASSERT_EQ(sewn.positions.size(), graded.garment.vertices.size());
  ASSERT_TRUE(graded.flat.has_value());
  // Placed round the shopper's body, not the chart body: the same panels, other places.
  const UnsewnGarment cut = first.cutOn(kShopper, Sex::Female, "pencilskirt", "M");
  EXPECT_EQ(cut.placed.triangles, graded.garment.triangles);
  EXPECT_NE(cut.placed.vertices, graded.garment.vertices);
  // Sewn shut: every seam's two sides meet in the drape.
  EXPECT_LE(largestSeamGap(cut, sewn.positions), 2e-3);
  EXPECT_GT(largestSeamGap(cut, cut.placed.vertices), 0.1);  // the control: placed, they gape
  // A generator's style has nothing to sew.
  EXPECT_THROW(first.cutOn(kShopper, Sex::Female, "pencil", "M"), std::invalid_argument);
  FitWorker second(shop.chart(), &shop);  // another worker, the same cache
  second.useCache(cache);
  const GarmentDrape found = second.sizeDrape(kShopper, Sex::Female, "pencilskirt", "M");
  EXPECT_TRUE(found.report.fromCache);
  EXPECT_EQ(found.positions, sewn.positions);
}

TEST_F(FitWorkerTest, AnAdvicesSizesDrapedSideBySideAreTheSizesDrapedOneByOne) {
  FitRequest pencil;
  pencil.sex = Sex::Female;
  pencil.style = "pencil";
  pencil.body = kShopper;
  FitWorker oneByOne(test::shippedCatalogue().chart()), sideBySide(test::shippedCatalogue().chart());
  oneByOne.drapeSizesOn(1);
  sideBySide.drapeSizesOn(3);
  const FitWorker::Answer alone = oneByOne.advise(pencil), together = sideBySide.advise(pencil);
  ASSERT_EQ(together.status, 200) << together.body;
  EXPECT_EQ(oneByOne.sizesDrapedSideBySide(), 0);
  EXPECT_EQ(sideBySide.sizesDrapedSideBySide(), 3);  // the three candidates, on threads of their own
  EXPECT_EQ(together.body, alone.body);              // the same advice, to the figure
  for (const char* size : {"S", "M", "L"})
    EXPECT_EQ(sideBySide.sizeDrape(kShopper, Sex::Female, "pencil", size).positions,
              oneByOne.sizeDrape(kShopper, Sex::Female, "pencil", size).positions)
        << size;
  // Drapes it has are not made again: another advice on the same body drapes nothing.
  ASSERT_EQ(sideBySide.advise(pencil).body, together.body);
  EXPECT_EQ(sideBySide.sizesDrapedSideBySide(), 3);
}
