// The fit map drawn in a scene: a ClothingLayer's garment becomes a face set of the same
// faces coloured per vertex by band, in the fit map's eight colours, seen from both sides;
// each vertex's band follows its value (a tube 2 cm off a cylinder: ease 17 mm everywhere,
// one band; no stretch, the first band).

#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>
#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoMaterialBinding.h>
#include <Inventor/nodes/SoSeparator.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <sstream>
#include <string>

#include "headless/InitHeadless.h"
#include "io/MeshExport.h"
#include "nodes/render/ClothingLayer.h"
#include "session/FitMapDrawing.h"
#include "session/SceneSession.h"
#include "support/FitTubes.h"
#include "support/TempDir.h"

using namespace figment::session;

namespace {

constexpr double kBody = 0.15, kOff = 0.02, kClearance = 0.003;  // m

std::string tubeScene() {
  const figment::TriangleMesh tube = figment::test::tube(kBody + kOff);
  std::ostringstream text;
  text << "#Inventor V2.1 ascii\nSeparator {\n  DEF Body MeshFile { fileName \"cylinder.obj\" }\n  Separator {\n"
       << "    Coordinate3 { point = DEF Tube ClothEngine {\n restPoints [";
  for (const figment::Vec3& p : tube.vertices) text << ' ' << p.x() << ' ' << p.y() << ' ' << p.z() << ',';
  text << " ]\n coordIndex [";
  for (const figment::Triangle& t : tube.triangles) text << ' ' << t[0] << ' ' << t[1] << ' ' << t[2] << " -1,";
  text << " ]\n body USE Body material \"cotton\" integrator IMPLICIT timeStep 0.001 maxTime 0.002 clearance "
       << kClearance << "\n    } . positions }\n    ClothingLayer { coordIndex = USE Tube.coordIndex }\n  }\n}\n";
  return text.str();
}

template <class T>
T* findIn(SoNode* root) {
  SoSearchAction search;
  search.setType(T::getClassTypeId());
  search.apply(root);
  return search.getPath() ? static_cast<T*>(search.getPath()->getTail()) : nullptr;
}

// The tube draped round the cylinder in `dir`, and its one garment's fit.
void drapeTube(const figment::test::TempDir& dir, SceneSession& session, std::vector<EngineFit>& fits) {
  figment::initHeadless();
  figment::exportObj(figment::test::cylinder(kBody), (dir.path() / "cylinder.obj").string());
  ASSERT_TRUE(session.load(dir.file("scene.iv", tubeScene()))) << session.loadError();
  session.drape();
  ASSERT_EQ(session.firstError(), "");
  fits = measureEngineFits(session.scene(), false, nullptr);
  ASSERT_EQ(fits.size(), 1u);
}

}  // namespace

TEST(FitMapDrawing, ColoursTheGarmentsVerticesByTheirBands) {
  figment::test::TempDir dir;
  SceneSession session;
  std::vector<EngineFit> fits;
  ASSERT_NO_FATAL_FAILURE(drapeTube(dir, session, fits));

  // Unstretched: every vertex in the first band. 17 mm off the skin (the stand-off less the
  // clearance, within the chords' 0.2 mm): one band, 1 - 17/50 of the way to red.
  for (const int band : fitMapBands(fits[0], figment::FitMapKind::Stretch)) EXPECT_EQ(band, 0);
  const std::vector<int> ease = fitMapBands(fits[0], figment::FitMapKind::Ease);
  const int expected = figment::fitMapBand(1.0 - (kOff - kClearance) / figment::kEaseMapRange);
  for (const int band : ease) EXPECT_EQ(band, expected);

  const int faces = findIn<ClothingLayer>(session.scene())->coordIndex.getNum();
  drawFitMap(fits[0], ease);
  EXPECT_EQ(findIn<ClothingLayer>(session.scene()), nullptr);  // replaced
  auto* set = findIn<SoIndexedFaceSet>(session.scene());
  ASSERT_NE(set, nullptr);
  ASSERT_EQ(set->coordIndex.getNum(), faces);
  ASSERT_EQ(set->materialIndex.getNum(), faces);
  for (int i = 0; i < faces; ++i) EXPECT_EQ(set->materialIndex[i], set->coordIndex[i] < 0 ? -1 : expected) << i;
  auto* material = findIn<SoMaterial>(session.scene());
  ASSERT_NE(material, nullptr);
  ASSERT_EQ(material->diffuseColor.getNum(), figment::kFitMapBands);
  const figment::Vec3 red = figment::fitMapColour(figment::kFitMapBands - 1);
  EXPECT_FLOAT_EQ(material->diffuseColor[figment::kFitMapBands - 1][0], float(red.x()));
  EXPECT_EQ(findIn<SoMaterialBinding>(session.scene())->value.getValue(), SoMaterialBinding::PER_VERTEX_INDEXED);
}

// A frame's map (figment-view --frames): the bands of another state of the drape, the tube
// stretched 2.2 % round (55 % of cotton's 4 % limit: band 4 of 8, from 50 to 62.5 %, the
// sections' largest strain being the round one; float positions move it by 1e-7), and the face set drawn coloured again
// by them.
TEST(FitMapDrawing, AnotherStateOfTheDrapeIsColouredByItsOwnBands) {
  figment::test::TempDir dir;
  SceneSession session;
  std::vector<EngineFit> fits;
  ASSERT_NO_FATAL_FAILURE(drapeTube(dir, session, fits));
  std::vector<SbVec3f> stretched;
  for (const figment::Vec3& p : fits[0].rest.vertices)
    stretched.emplace_back(float(1.022 * p.x()), float(p.y()), float(1.022 * p.z()));
  const std::vector<int> bands = fitMapBands(fits[0], stretched, 0.0, figment::FitMapKind::Stretch);
  ASSERT_EQ(bands.size(), stretched.size());
  const int expected = figment::fitMapBand(0.022 / figment::fabricLimits("cotton").stretch);
  ASSERT_EQ(expected, 4);
  EXPECT_EQ(std::count(bands.begin(), bands.end(), expected), std::ptrdiff_t(bands.size()));
  // The drape as it ended is unstretched: the first band, drawn; then coloured by the frame's.
  const std::vector<SoIndexedFaceSet*> drawn = drawFitMap(fits[0], fitMapBands(fits[0], figment::FitMapKind::Stretch));
  ASSERT_EQ(drawn.size(), 1u);
  EXPECT_EQ(drawn[0]->materialIndex[0], 0);
  colourFitMap(drawn[0], bands);
  int wrong = 0;
  for (int i = 0; i < drawn[0]->coordIndex.getNum(); ++i)
    wrong += drawn[0]->materialIndex[i] != (drawn[0]->coordIndex[i] < 0 ? -1 : expected);
  EXPECT_EQ(wrong, 0);
}
