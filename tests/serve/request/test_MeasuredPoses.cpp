// A measured body's poses: MakeHuman's rig presets by name, each the HumanBody pose of the
// same preset (OutfitScene sets the node's enum from the preset's value).

#include <gtest/gtest.h>

#include "nodes/body/HumanBody.h"
#include "serve/request/MeasuredPoses.h"

using namespace figment;
using namespace figment::serve;

TEST(MeasuredPoses, EachNamesTheHumanBodysPoseOfItsPreset) {
  const std::pair<const char*, int> expected[] = {{"rest", HumanBody::A_POSE},
                                                  {"arms-down", HumanBody::ARMS_DOWN},
                                                  {"arm-raised", HumanBody::ARM_RAISED},
                                                  {"walking", HumanBody::WALKING_STEP},
                                                  {"sitting", HumanBody::SITTING}};
  ASSERT_EQ(MeasuredPoses::all().size(), std::size(expected));
  for (const auto& [name, pose] : expected) {
    const MeasuredPose* found = MeasuredPoses::find(name);
    ASSERT_NE(found, nullptr) << name;
    EXPECT_EQ(int(found->preset), pose) << name;
  }
  EXPECT_EQ(MeasuredPoses::find("relaxed"), nullptr);  // the Mannequin's
  EXPECT_EQ(MeasuredPoses::names(), "rest, arms-down, arm-raised, walking, sitting");
}
