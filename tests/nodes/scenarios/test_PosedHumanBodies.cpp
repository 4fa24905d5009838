// The posed HumanBody scenes (scenes/human-posed-*.iv) as ClothEngine drapes them: the
// engine drives the body from rest into its pose by the drape's clock, and the garment
// comes to rest with no node inside the posed body.
// Skipped when MakeHuman's data is absent (scripts/setup.sh fetches it).
#include <Inventor/fields/SoMFVec3f.h>
#include <gtest/gtest.h>

#include <ostream>
#include <string>

#include "io/MakeHumanFiles.h"
#include "nodes/body/HumanBody.h"
#include "sim/collision/MeshCollider.h"
#include "support/ShippedGarmentScene.h"

using namespace figment::test;

namespace {

struct PosedScene {
  std::string scene;
  bool rests;
};

void PrintTo(const PosedScene& posed, std::ostream* out) {
  *out << posed.scene;
}

class PosedHumanBodies : public ::testing::TestWithParam<PosedScene> {};

TEST_P(PosedHumanBodies, DrapeIntoThePoseWithNoNodeInside) {
  if (figment::findMakeHumanData().empty()) GTEST_SKIP() << "MakeHuman's data not found";
  const ShippedGarmentScene scene(GetParam().scene);
  ASSERT_NE(scene.engine(), nullptr);
  ClothEngine& engine = *scene.engine();
  SoMFVec3f positions;
  positions.connectFrom(&engine.positions);
  positions.evaluate();
  ASSERT_EQ(engine.lastError(), "");
  EXPECT_EQ(engine.lastRun().atRest, GetParam().rests) << "t = " << engine.lastRun().simulatedSeconds << " s";
  auto* body = dynamic_cast<HumanBody*>(engine.body.getValue());
  ASSERT_NE(body, nullptr);
  const std::shared_ptr<const figment::MeshCollider> posed = body->collider();  // the body as drawn
  int inside = 0;
  for (int i = 0; i < positions.getNum(); ++i) {
    const SbVec3f& p = positions[i];
    figment::Contact contact;
    if (posed->contact(figment::Vec3(p[0], p[1], p[2]), 0.0, 0.05, contact) && contact.distance < -0.001) ++inside;
  }
  EXPECT_EQ(inside, 0);
}

INSTANTIATE_TEST_SUITE_P(Scenes, PosedHumanBodies,
                         ::testing::Values(PosedScene{"human-posed-arm.iv", true},
                                           PosedScene{"human-posed-walk.iv", true},
                                           PosedScene{"human-posed-sitting.iv", true}));

}  // namespace
