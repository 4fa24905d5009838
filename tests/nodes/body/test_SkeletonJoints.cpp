// The skeleton's joints as fields: written and read back in the humanoid's order whatever the
// order in the file, and each bad list refused with the entry that is wrong.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "nodes/body/SkeletonJoints.h"
#include "sim/body/Skeleton.h"
#include "support/Refusal.h"
#include "support/SceneTestSupport.h"

using namespace figment::test;

namespace {

class SkeletonJointsTest : public testing::Test {
 protected:
  void SetUp() override {
    initCoin();
    joints_ = new SkeletonJoints;
    joints_->ref();
  }
  void TearDown() override { joints_->unref(); }
  std::string refusal() const {
    return figment::test::refusal([&] { joints_->skeleton(); });
  }
  SkeletonJoints* joints_ = nullptr;
};

TEST_F(SkeletonJointsTest, RoundTripsTheHumanoidInAnyOrder) {
  std::vector<figment::Vec3> positions;
  for (size_t i = 0; i < figment::humanoidJointNames().size(); ++i) positions.emplace_back(0.01 * i, 1, 0);
  joints_->setSkeleton(figment::humanoidSkeleton(positions));
  // Swap the first two entries: the order in the file does not matter.
  const SbString first = joints_->names[0];
  const SbVec3f firstAt = joints_->positions[0];
  joints_->names.set1Value(0, joints_->names[1]);
  joints_->positions.set1Value(0, joints_->positions[1]);
  joints_->names.set1Value(1, first);
  joints_->positions.set1Value(1, firstAt);
  const figment::Skeleton skeleton = joints_->skeleton();
  ASSERT_EQ(skeleton.joints.size(), positions.size());
  for (size_t i = 0; i < positions.size(); ++i)
    EXPECT_TRUE(skeleton.joints[i].position.isApprox(positions[i], 1e-6)) << skeleton.joints[i].name;
}

TEST_F(SkeletonJointsTest, RefusesABadListNamingTheEntry) {
  joints_->names.setValue("pelvis");
  EXPECT_EQ(refusal(), "SkeletonJoints: 1 names but 0 positions");
  joints_->positions.setValue(SbVec3f(0, 1, 0));
  joints_->names.setValue("tail");
  EXPECT_EQ(refusal(), "SkeletonJoints: names[0] = \"tail\" is not a joint of the humanoid skeleton");
  const char* twice[] = {"pelvis", "pelvis"};
  joints_->names.setValues(0, 2, twice);
  joints_->positions.set1Value(1, SbVec3f(0, 1, 0));
  EXPECT_EQ(refusal(), "SkeletonJoints: names[1] = \"pelvis\" repeats");
  joints_->names.setValue("pelvis");
  joints_->positions.setNum(1);
  EXPECT_EQ(refusal(), "SkeletonJoints: names has no \"waist\"");  // the first in the humanoid's order
}

}  // namespace
