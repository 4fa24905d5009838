// A tolerance's choice without a scene: the fastest configuration within it that the body
// allows, the body it then collides with, and the faster ones passed over, each with why.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "sim/collision/MeshCollider.h"
#include "sim/drape/MethodChoice.h"
#include "support/TestMeshes.h"

using namespace figment;

namespace {

MethodTable table() {
  return {"table.csv",
          {{"implicit:0.02", "triangles", "off", 1.0, 3, 0.3, 1.0},
           {"implicit:0.05", "volumes", "off", 1.0, 3, 0.4, 2.0},
           {"implicit:0.05", "capsules", "off", 1.0, 3, 0.4, 0.5},
           {"implicit:0.01", "mix", "off", 1.0, 3, 0.2, 3.0},
           {"implicit:0.1", "volumes", "off", 2.0, 3, 0.5, 0.1}}};
}

// A jointed body of radial volumes whose own triangles are a ball; `made` counts the
// triangles built, `parts` the parts asked to collide by their triangles.
struct JointedBody {
  std::shared_ptr<const Collider> volumes = std::make_shared<MeshCollider>(meshes::sphere(0.2, 16, 8));
  std::shared_ptr<const Collider> ball = std::make_shared<MeshCollider>(meshes::sphere(0.2, 24, 12));
  std::shared_ptr<const Collider> mixed = std::make_shared<MeshCollider>(meshes::sphere(0.21, 16, 8));
  int made = 0;
  std::vector<int> parts{-1};

  DrapeBody body() {
    DrapeBody b;
    b.collider = volumes;
    b.description = {"mannequin", {{"radial_volumes", 14}}};
    b.jointed = true;
    b.triangles = [this] {
      ++made;
      return ball;
    };
    b.trianglesDescription = {"mesh", {{"triangles", 100}}};
    b.withExactParts = [this](const std::vector<int>& asked) {
      parts = asked;
      return mixed;
    };
    return b;
  }
};

std::string errorOf(const MethodTable& t, double tolerance, const DrapeBody& body) {
  try {
    chooseMethod(t, tolerance, body, {});
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(MethodChoice, TheFastestWithinThatTheBodyAllowsAndItsBody) {
  JointedBody jointed;
  const MethodChoice choice = chooseMethod(table(), 0.35, jointed.body(), {});
  EXPECT_EQ(choice.picked.method, "implicit:0.02");
  EXPECT_EQ(choice.body, jointed.ball);  // its own triangles, built for this choice
  EXPECT_EQ(jointed.made, 1);
  EXPECT_EQ(choice.bodyDescription.kind, "mesh");
  EXPECT_EQ(choice.passedOver, "");
  // Wider: the capsules are faster but this body has none; its volumes are next.
  const MethodChoice wider = chooseMethod(table(), 0.45, jointed.body(), {});
  EXPECT_EQ(wider.picked.body, "triangles");
  EXPECT_EQ(wider.passedOver,
            "implicit:0.05, capsules, progressive off (the Mannequin's volumes are not all capsules)");
}

TEST(MethodChoice, APosedBodysTrianglesArePassedOverSayingWhy) {
  JointedBody jointed;
  DrapeBody posed = jointed.body();
  posed.poseOrSize = "posed (rotatedJoints)";
  const MethodChoice choice = chooseMethod(table(), 0.45, posed, {});
  EXPECT_EQ(choice.picked.label(), "implicit:0.05, volumes, progressive off");
  EXPECT_EQ(choice.body, jointed.volumes);
  EXPECT_EQ(choice.bodyDescription.kind, "mannequin");
  EXPECT_EQ(jointed.made, 0);  // never built when not picked
  EXPECT_NE(choice.passedOver.find("implicit:0.02, triangles, progressive off (the Mannequin's triangles are its "
                                   "rest pose and size, and it is posed (rotatedJoints))"),
            std::string::npos)
      << choice.passedOver;
}

TEST(MethodChoice, MixCollidesByTheTrianglesOfThePartsTheGarmentMeets) {
  JointedBody jointed;
  const MethodChoice choice = chooseMethod(table(), 0.25, jointed.body(), {Vec3(0.0, 0.2, 0.0)});
  EXPECT_EQ(choice.picked.body, "mix");
  EXPECT_EQ(choice.body, jointed.mixed);
  EXPECT_TRUE(jointed.parts.empty());  // a mesh has no parts: none asked by name
}

TEST(MethodChoice, NothingUsableIsOneLineNamingTheToleranceTableAndWhy) {
  DrapeBody mesh;
  mesh.collider = std::make_shared<MeshCollider>(meshes::sphere(0.2, 16, 8));
  mesh.description = {"mesh", {}};
  const std::string line = errorOf(table(), 0.5, mesh);
  EXPECT_NE(line.find("tolerance = 0.5: no configuration measured within it (table.csv) suits this body: "),
            std::string::npos)
      << line;
  EXPECT_NE(line.find("(the body is no Mannequin)"), std::string::npos) << line;
  JointedBody jointed;
  EXPECT_NE(errorOf(table(), 0.15, jointed.body()).find("tolerance = 0.15: no configuration"), std::string::npos);
}

TEST(MethodChoice, WhyABodyCannotUseAConfiguration) {
  JointedBody jointed;
  const DrapeBody radial = jointed.body();
  EXPECT_EQ(whyUnusable(radial, table().configurations[1]), "");
  EXPECT_EQ(whyUnusable(radial, table().configurations[4]), "measured on a resampled garment");
  DrapeBody capsules = radial;
  capsules.description.counts = {{"capsule_volumes", 14}};
  EXPECT_EQ(whyUnusable(capsules, table().configurations[2]), "");
  EXPECT_EQ(whyUnusable(capsules, table().configurations[1]), "the Mannequin's volumes are not all radial");
  DrapeBody bare = radial;
  bare.triangles = nullptr;
  EXPECT_EQ(whyUnusable(bare, table().configurations[0]), "the Mannequin has no body mesh");
  MeasuredConfiguration odd = table().configurations[0];
  odd.body = "clouds";
  EXPECT_EQ(whyUnusable(radial, odd), "an unknown body \"clouds\"");
}

TEST(MethodChoice, NoPartsWhereTheBodyIsNoSetOfVolumes) {
  const MeshCollider ball(meshes::sphere(0.2, 16, 8));
  EXPECT_TRUE(partsWhereGarmentMeets(ball, {Vec3(0.0, 0.2, 0.0)}).empty());
}
