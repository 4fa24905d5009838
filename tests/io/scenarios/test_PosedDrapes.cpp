// Dressed in any pose (issue 30): the garment is made round the rest body and put on in
// the rest pose, and the body turns into its pose over simulated time as the drape runs
// (sim/collision/MovingMeshCollider.h), so the pose does not tangle the garment. At the
// end no node lies inside the posed body and the raised arm's sleeve rests on the arm.
// Skipped when MakeHuman's data is absent (scripts/setup.sh fetches it).

#include <gtest/gtest.h>

#include <cstdio>

#include "io/MakeHumanFiles.h"
#include "io/MakeHumanLibrary.h"
#include "io/MakeHumanRig.h"
#include "sim/body/PosePresets.h"
#include "sim/body/RigSkin.h"
#include "sim/collision/MovingMeshCollider.h"
#include "sim/drape/GarmentDrape.h"
#include "sim/garment/FlaredSkirt.h"
#include "sim/garment/TShirt.h"

using namespace figment;

namespace {

class PosedDrapes : public ::testing::Test {
 protected:
  void SetUp() override {
    if (human.dir().empty()) GTEST_SKIP() << "MakeHuman's data not found";
    model = &human.model();
    rig.emplace(readHumanRig(human.dir(), model->base().fileVertexCount));
    skin = bindSkin(*rig, model->base().fileIndex);
    rest = model->make(parameters);
    placed = rig->place(model->fileVertices(parameters));
  }
  std::vector<Vec3> shapeAt(const RigPose& pose, double share) const {
    return skinVertices(skin, boneTransforms(*rig, placed, pose.partway(share)), rest.vertices,
                        SkinningMethod::DualQuaternion);
  }
  // The garment draped while the body turns from rest into `pose`, for at most `settle` s
  // after the body arrived.
  GarmentDrape drape(const TriangleMesh& garment, const RigPose& pose, double settle = 10.0) const {
    auto moving = std::make_shared<const MovingMeshCollider>(
        rest.triangles, [this, pose](double share) { return shapeAt(pose, share); }, 0.0);
    DrapeRequest request;
    request.garment = garment;
    request.parameters.material.thickness = 0.0006;
    request.parameters.integrator = Integrator::Implicit;
    request.parameters.timeStep = 0.05;
    request.parameters.maxTime = moving->duration() + settle;
    request.parameters.friction = 0.5;
    request.parameters.clearance = 0.006;
    request.body = moving;
    request.bodyClock = [moving](double time) { moving->advanceTo(time); };
    const GarmentDrape out = drapeGarment(request);
    std::printf(
        "pose motion %.2f s (%d keyframes), drape %.2f s simulated, %s (fastest %.4f m/s), stretch %.2f, %.1f s wall\n",
        moving->duration(), moving->keyframes(), out.report.run.simulatedTime,
        out.report.run.atRest ? "at rest" : "NOT at rest", out.report.run.maxSpeed, out.report.run.maxStretch,
        out.report.run.wallSeconds);
    return out;
  }
  // Nodes inside the posed body (deeper than 1 mm).
  int nodesInside(const std::vector<Vec3>& nodes, const RigPose& pose) const {
    TriangleMesh posed = rest;
    posed.vertices = shapeAt(pose, 1.0);
    const MeshCollider body(posed);
    int inside = 0;
    for (const Vec3& p : nodes) {
      Contact c;
      if (body.contact(p, 0.0, 0.05, c) && c.distance < -0.001) ++inside;
    }
    return inside;
  }
  Vec3 posedHead(const RigPose& pose, const std::string& bone) const {
    const int b = rig->require(bone);
    return boneTransforms(*rig, placed, pose)[b] * placed[b].head;
  }

  HumanParameters parameters;
  MakeHumanLibrary human;
  const HumanModel* model = nullptr;  // human's
  std::optional<HumanRig> rig;
  RigSkin skin;
  TriangleMesh rest;
  std::vector<PlacedBone> placed;
};

}  // namespace

TEST_F(PosedDrapes, TheRaisedArmCarriesTheSleeveUpAndTheShirtRestsWithNoNodeInside) {
  const TShirt shirt = makeTShirt(rest);
  const RigPose pose = presetPose(PosePreset::ArmRaised, *rig, placed);
  const GarmentDrape out = drape(shirt.mesh, pose);
  const std::vector<Vec3>& x = out.positions;
  EXPECT_TRUE(out.report.run.atRest);
  EXPECT_LT(out.report.run.maxStretch, 1.5);  // not torn at the armpit as the arm rose (DrapeVerdict)
  EXPECT_EQ(nodesInside(x, pose), 0);
  // The left sleeve: the nodes beyond the rest shoulder joint, round the upper arm.
  const int upper = rig->require("upperarm01.L");
  const Vec3 shoulder = posedHead(pose, "upperarm01.L"), elbow = posedHead(pose, "lowerarm01.L");
  const Vec3 axis = elbow - shoulder;
  TriangleMesh posed = rest;
  posed.vertices = shapeAt(pose, 1.0);
  const MeshCollider body(posed);
  int sleeve = 0, roundArm = 0, above = 0, onTop = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    if (shirt.mesh.vertices[i].x() < placed[upper].head.x() + 0.05) continue;
    ++sleeve;
    const double t = std::clamp((x[i] - shoulder).dot(axis) / axis.squaredNorm(), 0.0, 1.0);
    const Vec3 off = x[i] - (shoulder + t * axis);
    // round the raised upper arm (its radius and the sleeve's sag below it), not left
    // behind at the side where the arm was
    if (off.norm() < 0.12) ++roundArm;
    if (off.y() > 0.0) {
      ++above;
      Contact c;
      if (body.contact(x[i], 0.015, 0.05, c)) ++onTop;  // resting on the arm
    }
  }
  ASSERT_GT(sleeve, 20);
  EXPECT_EQ(roundArm, sleeve);
  EXPECT_GT(onTop, above / 2);
}

TEST_F(PosedDrapes, SittingWithTheSkirtRestsWithNoNodeInside) {
  const FlaredSkirt skirt = makeFlaredSkirt(rest);
  const RigPose pose = presetPose(PosePreset::Sitting, *rig, placed);
  // Slowly: its hem creeps over the knees at 1 to 4 cm/s for some 20 s (docs/bodies.md).
  const GarmentDrape out = drape(skirt.mesh, pose, 30.0);
  EXPECT_TRUE(out.report.run.atRest);
  EXPECT_LT(out.report.run.maxStretch, 1.5);
  EXPECT_EQ(nodesInside(out.positions, pose), 0);
}

TEST_F(PosedDrapes, AKneeBent60DegreesWithTheSkirtRestsWithNoNodeInside) {
  const FlaredSkirt skirt = makeFlaredSkirt(rest);
  RigPose pose;
  pose.set(rig->require("lowerleg01.L"), Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 3, Vec3::UnitX())));
  const GarmentDrape out = drape(skirt.mesh, pose);
  EXPECT_TRUE(out.report.run.atRest);
  EXPECT_LT(out.report.run.maxStretch, 1.5);
  EXPECT_EQ(nodesInside(out.positions, pose), 0);
}
