// A scene's draped garments as figment-view's --fit-map and --stats see them: each
// ClothingLayer drawn from a ClothEngine's positions on a mesh body is found with its
// rest shape, drape, body and fabric; an engine on no mesh body, or not drawn by a
// ClothingLayer, is not. A tube standing 2 cm off a cylinder (tests/support/FitTubes.h)
// reports its ease and no stretch.

#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "headless/InitHeadless.h"
#include "io/MeshExport.h"
#include "session/EngineFit.h"
#include "session/SceneSession.h"
#include "support/FitTubes.h"
#include "support/TempDir.h"

namespace test_EngineFit {

using namespace figment::session;

namespace {

constexpr double kBody = 0.15, kOff = 0.02;  // m: the cylinder's radius, the tube's stand-off

// The tube as a ClothEngine's fields: its rest points and faces.
std::string tubeFields() {
  const figment::TriangleMesh tube = figment::test::tube(kBody + kOff);
  std::ostringstream text;
  text << "restPoints [";
  for (const figment::Vec3& p : tube.vertices) text << ' ' << p.x() << ' ' << p.y() << ' ' << p.z() << ',';
  text << " ]\n coordIndex [";
  for (const figment::Triangle& t : tube.triangles) text << ' ' << t[0] << ' ' << t[1] << ' ' << t[2] << " -1,";
  text << " ]\n";
  return text.str();
}

// A scene of the cylinder (an OBJ beside it) and the tube drawn by a ClothingLayer (or an
// IndexedFaceSet), its engine's `body` field as given: 2 ms simulated, so the drape is the rest shape.
std::string scene(const std::string& shape, const std::string& body, const std::string& material) {
  return "#Inventor V2.1 ascii\nSeparator {\n  DEF Body MeshFile { fileName \"cylinder.obj\" }\n"
         "  Separator {\n    Coordinate3 { point = DEF Tube ClothEngine {\n" +
         tubeFields() + " " + body + " material \"" + material +
         "\" integrator IMPLICIT timeStep 0.001 maxTime 0.002 clearance 0.003\n    } . positions }\n    " + shape +
         " { coordIndex = USE Tube.coordIndex }\n  }\n}\n";
}

class EngineFitTest : public ::testing::Test {
 protected:
  void SetUp() override {
    figment::initHeadless();
    figment::exportObj(figment::test::cylinder(kBody), (dir_.path() / "cylinder.obj").string());
  }
  // The fits of the scene, draped.
  std::vector<EngineFit> fits(const std::string& text) {
    session_.clear();
    const std::string path = dir_.file("scene-" + std::to_string(++scenes_) + ".iv", text);
    EXPECT_TRUE(session_.load(path)) << session_.loadError();
    session_.drape();
    EXPECT_EQ(session_.firstError(), "");
    return measureEngineFits(session_.scene(), false, nullptr);
  }
  figment::test::TempDir dir_;
  SceneSession session_;
  int scenes_ = 0;
};

}  // namespace

TEST_F(EngineFitTest, FindsTheDrawnGarmentWithItsBodyAndFabric) {
  const std::vector<EngineFit> found = fits(scene("ClothingLayer", "body USE Body", "jersey"));
  ASSERT_EQ(found.size(), 1u);
  const EngineFit& fit = found[0];
  EXPECT_EQ(fit.name, "Tube");
  EXPECT_EQ(fit.layers.size(), 1u);
  ASSERT_EQ(fit.rest.vertices.size(), size_t((figment::test::kRows + 1) * figment::test::kColumns));
  ASSERT_EQ(fit.positions.size(), fit.rest.vertices.size());
  ASSERT_NE(fit.body, nullptr);
  EXPECT_DOUBLE_EQ(fit.limits.stretch, figment::fabricLimits("jersey").stretch);
  EXPECT_DOUBLE_EQ(fit.parameters.clearance, 0.003);
  EXPECT_TRUE(fit.regions.empty());  // not asked for
  EXPECT_TRUE(fit.garment.empty());  // not a catalogue garment
  // The drape is the tube where it was cut: 2 cm off the skin, unstretched. Its ease, as
  // the fit measures it (the stand-off less the clearance, on the cylinder's chords: the
  // facets lie within (1 - cos(pi / 64)) r of its radius).
  const figment::FitRegion region = figment::test::middle(kBody);
  const std::vector<figment::RegionFit> measured = figment::measureFit(fit.input(), {region});
  ASSERT_TRUE(measured[0].covered());
  EXPECT_NEAR(measured[0].ease, kOff - 0.003, 0.001);
  EXPECT_NEAR(measured[0].meanStrain, 0.0, 1e-3);
}

TEST_F(EngineFitTest, LeavesOutGarmentsNotOnAMeshOrNotDrawnByAClothingLayer) {
  EXPECT_TRUE(fits(scene("IndexedFaceSet", "body USE Body", "jersey")).empty());
  EXPECT_TRUE(fits(scene("ClothingLayer", "", "jersey")).empty());  // no body
}

TEST_F(EngineFitTest, AnUnknownFabricHasTheWovenLimits) {
  const std::vector<EngineFit> found = fits(scene("ClothingLayer", "body USE Body", ""));
  ASSERT_EQ(found.size(), 1u);
  EXPECT_DOUBLE_EQ(found[0].limits.stretch, figment::fabricLimits("cotton").stretch);
}

}  // namespace test_EngineFit
