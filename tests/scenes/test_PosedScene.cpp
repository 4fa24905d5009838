// scenes/posed.iv without draping it: the mannequin posed and sized through its fields,
// its skin and its collision volumes moved by the same transformations.
#include <Inventor/nodes/SoSeparator.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "guard/SceneFile.h"
#include "headless/InitHeadless.h"
#include "nodes/SceneSearch.h"
#include "nodes/body/Mannequin.h"
#include "nodes/body/MeshFile.h"
#include "nodes/cloth/ClothEngine.h"
#include "sim/body/Skeleton.h"
#include "sim/body/Skinning.h"
#include "sim/collision/Collider.h"
#include "sim/collision/VolumeSetCollider.h"
#include "sim/core/TriangleMesh.h"
#include "sim/drape/DrapeReport.h"

namespace {

class PosedScene : public ::testing::Test {
 protected:
  void SetUp() override {
    figment::initHeadless();
    std::string error;
    scene_ = figment::guard::readScene(std::string(FIGMENT_SOURCE_DIR) + "/scenes/posed.iv", error);
    ASSERT_NE(scene_, nullptr) << error;
    scene_->ref();
    model_ = dynamic_cast<Mannequin*>(SoNode::getByName("Model"));
    ASSERT_NE(model_, nullptr);
    const auto* body = dynamic_cast<MeshFile*>(model_->body.getValue());
    ASSERT_NE(body, nullptr);
    for (int i = 0; i < body->point.getNum(); ++i)
      rest_.emplace_back(body->point[i][0], body->point[i][1], body->point[i][2]);
  }
  void TearDown() override {
    if (scene_) scene_->unref();
  }
  SoSeparator* scene_ = nullptr;
  Mannequin* model_ = nullptr;
  std::vector<figment::Vec3> rest_;
};

double top(const std::vector<figment::Vec3>& vertices) {
  double y = -1e9;
  for (const figment::Vec3& v : vertices) y = std::max(y, v.y());
  return y;
}

}  // namespace

TEST_F(PosedScene, IsPosedAndSizedByItsFields) {
  const std::vector<figment::Vec3>& posed = model_->posedBody().vertices;
  ASSERT_EQ(posed.size(), rest_.size());
  // height 0.98 about the floor (the head turns about the vertical: no change there).
  const double floor = [&] {
    double y = 1e9;
    for (const figment::Vec3& v : rest_) y = std::min(y, v.y());
    return y;
  }();
  EXPECT_NEAR((top(posed) - floor) / (top(rest_) - floor), 0.98, 0.003);
  // The right forearm is raised by its elbow: its fingertip moved by decimetres.
  const figment::Skeleton& skeleton = model_->skeleton();
  const figment::Vec3 fingertip = skeleton["fingertipR"].position;
  size_t nearest = 0;
  for (size_t i = 0; i < rest_.size(); ++i)
    if ((rest_[i] - fingertip).norm() < (rest_[nearest] - fingertip).norm()) nearest = i;
  EXPECT_GT((posed[nearest] - rest_[nearest]).norm(), 0.2);
}

TEST_F(PosedScene, TheSkinStaysInsideTheVolumesThatFollowIt) {
  // Every vertex that moves with one part alone (not blended near a joint) is as
  // enclosed posed as the fitted volumes enclose it at rest: within 0.1 mm.
  const figment::SkinWeights& weights = model_->skinWeights();
  const std::vector<figment::Vec3>& posed = model_->posedBody().vertices;
  const auto collider = model_->collider();
  int rigid = 0, outside = 0;
  for (size_t i = 0; i < posed.size(); ++i) {
    if (weights.vertices[i][0].weight < 1.0) continue;
    ++rigid;
    figment::Contact contact;
    if (!collider->contact(posed[i], 1e-4, 0.05, contact)) ++outside;
  }
  EXPECT_GT(rigid, static_cast<int>(posed.size() * 6 / 10)) << "most vertices are away from the joints";
  EXPECT_EQ(outside, 0) << "of " << rigid;
}

TEST_F(PosedScene, TheDressComesToRestOutsideThePosedVolumes) {
  // The drape on stretched and turned parts (the path a rigid pose never takes).
  const std::vector<ClothEngine*> engines = figment::findClothEngines(scene_);
  ASSERT_EQ(engines.size(), 1u);
  ClothEngine* engine = engines.front();
  SoMFVec3f draped;
  draped.connectFrom(&engine->positions);
  ASSERT_GT(draped.getNum(), 0);
  ASSERT_EQ(engine->lastError(), "");
  EXPECT_TRUE(engine->lastRun().run.atRest) << "simulated " << engine->lastRun().run.simulatedTime << " s";
  const auto volumes = std::static_pointer_cast<const figment::VolumeSetCollider>(model_->collider());
  int inside = 0;
  double top = -1e9;
  for (int i = 0; i < draped.getNum(); ++i) {
    const figment::Vec3 p(draped[i][0], draped[i][1], draped[i][2]);
    top = std::max(top, p.y());
    for (size_t k = 0; k < volumes->size(); ++k) inside += volumes->worldVolume(k).contains(p);
  }
  EXPECT_EQ(inside, 0);
  // Held up at the shoulders: the straps' top lies above the posed shoulders' top (the
  // body's highest point beside the neck, inside the arms, as in DefaultScene), and not
  // by more than a strap's width folded up (2 cm): it stands 11 mm above (on the paper's
  // explicit path the straps ride up in a fold; on the default scene's implicit drape
  // 3 mm). Before, a dress 17 cm lower passed.
  double shoulderTop = -1e9;
  for (const figment::Vec3& v : model_->posedBody().vertices)
    if (std::abs(v.x()) > 0.08 && std::abs(v.x()) < 0.20 && v.y() < 1.45) shoulderTop = std::max(shoulderTop, v.y());
  const double gap = top - shoulderTop;
  RecordProperty("dress_top_above_shoulder_mm", std::to_string(gap * 1000));
  EXPECT_GT(gap, 0.0) << "the dress slid down: its top " << -gap * 1000 << " mm below the shoulders'";
  EXPECT_LT(gap, 0.02) << "the dress floats " << gap * 1000 << " mm above the shoulders";
}
