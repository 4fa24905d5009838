// The skeleton's look-ups, the humanoid's hierarchy and the nearest-bone part of a vertex.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "sim/body/Skeleton.h"
#include "support/ArmSkeleton.h"

using namespace figment;

namespace {

TEST(Skeleton, FindsAJointByNameAndRefusesAnUnknownOneNamingIt) {
  const Skeleton s = test::armSkeleton();
  EXPECT_EQ(s.joint("elbow"), 1);
  EXPECT_EQ(s.joint("knee"), -1);
  EXPECT_EQ(s["wrist"].position, Vec3(2, 0, 0));
  try {
    (void)s["knee"];
    FAIL() << "an unknown joint was found";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("\"knee\""), std::string::npos) << e.what();
  }
}

TEST(Skeleton, AssignsEachVertexToItsNearestBone) {
  const std::vector<int> part =
      assignParts(test::armSkeleton(), {{0.5, 0.1, 0}, {1.6, -0.2, 0}, {-1, 0, 0}, {3, 0, 0}});
  EXPECT_EQ(part, (std::vector<int>{0, 1, 0, 1}));  // beyond an end: the bone that ends there
}

TEST(Skeleton, HumanoidHasItsJointsInOrderWithThePelvisAtTheRoot) {
  const std::vector<std::string>& names = humanoidJointNames();
  ASSERT_EQ(names.size(), 25u);
  std::vector<Vec3> positions;
  for (size_t i = 0; i < names.size(); ++i) positions.emplace_back(0, double(i), 0);
  const Skeleton s = humanoidSkeleton(positions);
  ASSERT_EQ(s.joints.size(), 25u);
  EXPECT_EQ(s.parts.size(), 17u);
  for (size_t i = 0; i < names.size(); ++i) {
    EXPECT_EQ(s.joints[i].name, names[i]);
    EXPECT_EQ(s.joints[i].position.y(), double(i));
  }
  EXPECT_EQ(s["pelvis"].parent, -1);
  EXPECT_EQ(s.joints[s["kneeL"].parent].name, "hipL");
  EXPECT_EQ(s.joints[s["shoulderBaseR"].parent].name, "chest");
  EXPECT_THROW(humanoidSkeleton({Vec3::Zero()}), std::invalid_argument);
}

}  // namespace
