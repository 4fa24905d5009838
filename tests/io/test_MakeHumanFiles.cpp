// MakeHuman's data as scripts/fetch-makehuman.py extracts it (io/MakeHumanFiles.h), and the
// bodies made from it: the base skin, the default bodies' measurements, bodies made to the
// body dimensions of a size chart (docs/bodies.md) and a set out of reach. Skipped when the
// data is absent (scripts/setup.sh fetches it).
#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>

#include "io/MakeHumanFiles.h"
#include "io/MeshExport.h"
#include "io/TargetLibrary.h"
#include "sim/body/MeasuredBody.h"
#include "support/GzipFile.h"
#include "support/IoTestSupport.h"

namespace test_MakeHumanFiles {

using namespace figment;
using figment::test::ScopedEnvironment;
using figment::test::TempDir;
using figment::test::writeGzip;

namespace {

class MakeHumanData : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = findMakeHumanData();
    if (dir_.empty()) GTEST_SKIP() << "MakeHuman's data not found (scripts/setup.sh fetches it)";
    library_ = std::make_unique<TargetLibrary>(dir_);
    model_ = std::make_unique<HumanModel>(loadHumanModel(dir_, *library_));
  }
  HumanParameters sex(double gender) const {
    HumanParameters p;
    p.macro.gender = gender;
    return p;
  }
  std::string dir_;
  std::unique_ptr<TargetLibrary> library_;
  std::unique_ptr<HumanModel> model_;
};

// One size of a chart: stature, bust (men: chest), waist and hip girths, m.
struct ChartSize {
  const char* name;
  double gender, stature, bust, waist, hip;
};

// German women's (DOB 32-42, stature 168 cm) and men's (44-54) body dimensions in EN 13402-3's
// 4 cm steps (docs/bodies.md); the sizes beyond: tests/io/scenarios/test_MeasuredBodies.cpp.
const ChartSize kChart[] = {
    {"women 32", 0, 1.68, 0.76, 0.60, 0.84}, {"women 34", 0, 1.68, 0.80, 0.64, 0.88},
    {"women 36", 0, 1.68, 0.84, 0.68, 0.92}, {"women 38", 0, 1.68, 0.88, 0.72, 0.96},
    {"women 40", 0, 1.68, 0.92, 0.76, 1.00}, {"women 42", 0, 1.68, 0.96, 0.80, 1.04},
    {"men 44", 1, 1.68, 0.88, 0.76, 0.92},   {"men 46", 1, 1.71, 0.92, 0.80, 0.96},
    {"men 48", 1, 1.74, 0.96, 0.84, 1.00},   {"men 50", 1, 1.77, 1.00, 0.88, 1.04},
    {"men 52", 1, 1.80, 1.04, 0.92, 1.08},   {"men 54", 1, 1.82, 1.08, 0.98, 1.12},
};

}  // namespace

TEST_F(MakeHumanData, TheSkinIsTheBodyGroupTriangulated) {
  const HumanBase base = readHumanBase(dir_);
  EXPECT_EQ(base.skin.vertices.size(), 13380u);       // hm08's skin, without its helper geometry
  EXPECT_EQ(base.skin.triangles.size(), 2 * 13378u);  // each quad two triangles
  EXPECT_EQ(base.fileVertexCount, 19158);
}

TEST_F(MakeHumanData, DefaultBodiesStandOnTheFloorAtAnAdultsStature) {
  for (double gender : {0.0, 1.0}) {
    const TriangleMesh body = model_->make(sex(gender));
    const Bounds b = boundsOf(body.vertices);
    EXPECT_DOUBLE_EQ(b.min.y(), 0.0);
    EXPECT_NEAR(b.min.x(), -b.max.x(), 1e-3);  // symmetric about x = 0
    const BodyMeasurements m = measureBody(body);
    // MakeHuman's average young adults: about 1.59 m (female) and 1.73 m (male)
    EXPECT_GT(m.stature, gender ? 1.65 : 1.52) << gender;
    EXPECT_LT(m.stature, gender ? 1.80 : 1.66) << gender;
    // the tape's landmarks in their order up the body
    const BodyLandmarks& l = m.landmarks;
    EXPECT_LT(l.crotch, l.hip);
    EXPECT_LT(l.hip, l.waist);
    EXPECT_LT(l.waist, l.underbust);
    EXPECT_LT(l.underbust, l.bust);
    EXPECT_LT(l.bust, l.armpit);
    EXPECT_LT(l.armpit, l.neck);
    EXPECT_LT(m.waistGirth, m.hipGirth);
    EXPECT_LT(m.neckGirth, m.waistGirth);
  }
}

TEST_F(MakeHumanData, SizeChartBodiesMeasureWithin5mmOfTheirDimensions) {
  const TempDir dir;
  for (const ChartSize& size : kChart) {
    HumanParameters start = sex(size.gender);
    const MeasuredBody made = makeMeasuredBody(
        *model_, start,
        {{"stature", size.stature}, {"bust_girth", size.bust}, {"waist_girth", size.waist}, {"hip_girth", size.hip}});
    // written and read back as figment-measure reads it, then measured anew
    const std::string path = (dir.path() / "body.obj").string();
    exportObj(numberedByFirstUse(made.body), path);
    const BodyMeasurements m = measureBody(importMesh(path).mesh);
    EXPECT_NEAR(m.stature, size.stature, 0.005) << size.name;
    EXPECT_NEAR(m.bustGirth, size.bust, 0.005) << size.name;
    EXPECT_NEAR(m.waistGirth, size.waist, 0.005) << size.name;
    EXPECT_NEAR(m.hipGirth, size.hip, 0.005) << size.name;
  }
}

TEST_F(MakeHumanData, ASetOutOfReachIsRefusedNamingTheMeasurement) {
  // hips 40 cm under the waist: no body has them
  try {
    makeMeasuredBody(*model_, sex(0), {{"waist_girth", 0.90}, {"hip_girth", 0.50}});
    FAIL() << "no exception";
  } catch (const UnreachableMeasurement& e) {
    EXPECT_NE(std::string(e.what()).find("hip_girth 0.500 m is out of reach"), std::string::npos) << e.what();
  }
  EXPECT_THROW(makeMeasuredBody(*model_, sex(0), {{"waist", 0.7}}), std::invalid_argument);
}

TEST_F(MakeHumanData, TargetsAreReadOnceAndAMissingOneIsNull) {
  const MorphTarget* bust = library_->find("torso/measure-bust-circ-incr");
  ASSERT_NE(bust, nullptr);
  EXPECT_FALSE(bust->vertices.empty());
  EXPECT_EQ(library_->find("torso/measure-bust-circ-incr"), bust);
  EXPECT_EQ(library_->find("macrodetails/proportions/female-baby-averagemuscle-averageweight-idealproportions"),
            nullptr);
}

TEST(MakeHumanFiles, ABadTargetLineNamesTheFile) {
  const TempDir dir;
  const std::string path = (dir.path() / "bad.target.gz").string();
  writeGzip(path, "12 0.1 0.2 0.3\n13 0.1 oops\n");
  try {
    readMorphTarget(path);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path + ": bad line '13 0.1 oops'"), std::string::npos) << e.what();
  }
  writeGzip(path, "12 0.1 0.2 0.3\n# a comment\n");
  EXPECT_EQ(readMorphTarget(path).vertices, std::vector<int>{12});
}

TEST(MakeHumanFiles, TheEnvironmentNamesTheDataFolder) {
  const TempDir dir;
  const ScopedEnvironment empty("FIGMENT_MAKEHUMAN_DIR", dir.path().string());
  EXPECT_EQ(findMakeHumanData(), "");  // named, but without 3dobjs/base.obj
  dir.file("3dobjs/base.obj", "v 0 0 0\n");
  EXPECT_EQ(findMakeHumanData(), dir.path().string());
  EXPECT_THROW(readHumanBase(dir.path().string()), std::runtime_error);  // no group 'body'
}

}  // namespace test_MakeHumanFiles
