// The display mesh (ClothingLayer.displaySubdivision, sim/core/DisplaySubdivision.h) on the
// shipped drapes keeps the cloth out of the body as well as the drape's own faces do. Those
// faces are drawn flat: between its vertices (every one outside the body's collision
// surface) a drawn face lies on the chords, which cut into a curved body where the drape
// pulls an edge across it (the T-shirt under the arms: flat subdivision, the faces' own
// points, puts 55 of 8,330 vertices up to 7.2 mm inside). The display mesh's vertices lie
// no deeper than those (by at most half a millimetre, a third of a pixel of a full-body
// picture 1200 pixels tall) and are not more often inside (beyond one in a thousand).
// Measured at two levels: the dress 0 inside (flat: 5, 2.4 mm deep), the T-shirt 39 of
// 8,330 and 7.4 mm (flat: 55 and 7.2 mm), the skirt 1 of 12,960 by 0.01 mm (flat: 0).
#include <Inventor/fields/SoMFVec3f.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "io/MeshImport.h"
#include "nodes/cloth/ClothEngineInputs.h"
#include "sim/collision/Collider.h"
#include "sim/core/DisplaySubdivision.h"
#include "sim/core/Subdivision.h"
#include "support/ShippedGarmentScene.h"

namespace test_DisplayMeshOnBodies {

using namespace figment::test;

namespace {

struct Drape {
  std::string scene;
  std::function<void(ClothEngine&)> configure;  // changes to the scene's own fields
};

void PrintTo(const Drape& drape, std::ostream* out) {
  *out << drape.scene;
}

struct Depths {
  int inside = 0;        // vertices inside the body
  double deepest = 0.0;  // m, the largest depth of one (0 when none is inside)
  size_t vertices = 0;
};

// How far inside `body` the vertices the triangles use lie.
Depths depths(const figment::Collider& body, const std::vector<figment::Vec3>& points,
              const std::vector<figment::Triangle>& triangles) {
  std::vector<bool> used(points.size(), false);
  for (const figment::Triangle& t : triangles)
    for (int v : t) used[v] = true;
  Depths out;
  for (size_t v = 0; v < points.size(); ++v) {
    if (!used[v]) continue;
    ++out.vertices;
    figment::Contact contact;
    if (body.contact(points[v], 0.0, 0.05, contact) && contact.distance < 0.0) {
      ++out.inside;
      out.deepest = std::max(out.deepest, -contact.distance);
    }
  }
  return out;
}

class DisplayMeshOnBodies : public ::testing::TestWithParam<Drape> {};

TEST_P(DisplayMeshOnBodies, IsNoDeeperInsideTheBodyThanTheDrapesFaces) {
  if (figment::findModelFile("human.zae").empty()) GTEST_SKIP() << "human.zae not found";
  const ShippedGarmentScene scene(GetParam().scene);
  ASSERT_NE(scene.engine(), nullptr);
  ClothEngine& engine = *scene.engine();
  GetParam().configure(engine);
  SoMFVec3f positions;
  positions.connectFrom(&engine.positions);
  positions.evaluate();
  ASSERT_EQ(engine.lastError(), "");
  const std::shared_ptr<const figment::Collider> body = figment::colliderFromBody(engine.body);
  ASSERT_NE(body, nullptr);
  figment::TriangleMesh drape{{}, figment::garmentFromFields(engine.restPoints, engine.coordIndex).triangles};
  for (int i = 0; i < positions.getNum(); ++i)
    drape.vertices.emplace_back(positions[i][0], positions[i][1], positions[i][2]);
  const Depths simulated = depths(*body, drape.vertices, drape.triangles);
  const figment::TriangleMesh flat = figment::subdivided(figment::subdivided(drape));
  const Depths chords = depths(*body, flat.vertices, flat.triangles);
  const figment::DisplaySubdivision layout(drape.triangles, drape.vertices, 2);
  std::vector<figment::Vec3> fine, normals;
  layout.apply(drape.vertices, fine, normals);
  const Depths display = depths(*body, fine, layout.triangles());
  EXPECT_LE(display.deepest, std::max(simulated.deepest, chords.deepest) + 5e-4);
  EXPECT_LE(display.inside, chords.inside + int(display.vertices / 1000));
  RecordProperty("simulatedInside", std::to_string(simulated.inside) + " of " + std::to_string(simulated.vertices));
  RecordProperty("simulatedDeepestMm", std::to_string(1e3 * simulated.deepest));
  RecordProperty("flatInside", std::to_string(chords.inside) + " of " + std::to_string(chords.vertices));
  RecordProperty("flatDeepestMm", std::to_string(1e3 * chords.deepest));
  RecordProperty("displayInside", std::to_string(display.inside) + " of " + std::to_string(display.vertices));
  RecordProperty("displayDeepestMm", std::to_string(1e3 * display.deepest));
}

void asShipped(ClothEngine&) {}

INSTANTIATE_TEST_SUITE_P(Scenes, DisplayMeshOnBodies,
                         ::testing::Values(Drape{"dress.iv", asShipped}, Drape{"tshirt.iv", asShipped},
                                           // As test_GarmentEdges drapes it: the implicit step.
                                           Drape{"skirt.iv",
                                                 [](ClothEngine& engine) {
                                                   engine.integrator = ClothEngine::IMPLICIT;
                                                   engine.timeStep = 0.05;
                                                   engine.maxTime = 10.0;
                                                 }}),
                         [](const ::testing::TestParamInfo<Drape>& param) {
                           return param.param.scene.substr(0, param.param.scene.find('.'));
                         });

}  // namespace

}  // namespace test_DisplayMeshOnBodies
