// figment-view's image options turned into views, frame times and paths.

#include <gtest/gtest.h>

#include "viewer/ImagePlan.h"

using namespace figment::viewer;

namespace {

std::optional<ImagePlan> plan(ImageOptions options, ImageOptionError& error) {
  if (options.output.empty()) options.output = "out.png";
  if (options.size.empty()) options.size = "80x60";
  return planImages(options, error);
}

}  // namespace

TEST(ImagePlan, OneImageByDefaultFromTheScenesCamera) {
  ImageOptionError error;
  const auto p = plan({}, error);
  ASSERT_TRUE(p);
  ASSERT_EQ(p->views.size(), 1u);
  EXPECT_FALSE(p->views[0]);
  EXPECT_TRUE(p->frameTimes.empty());
  EXPECT_EQ(p->paths, std::vector<std::string>{"out.png"});
}

TEST(ImagePlan, AnImagePerViewOrTurntableStepOrFrame) {
  ImageOptionError error;
  const auto views = plan({.views = {"front", "30,10"}}, error);
  ASSERT_TRUE(views);
  EXPECT_EQ(views->paths, (std::vector<std::string>{"out-0.png", "out-1.png"}));
  EXPECT_DOUBLE_EQ(views->views[1]->azimuth, 30.0);
  EXPECT_FALSE(views->oneDistance) << "each view frames the scene itself";

  const auto turntable = plan({.views = {"45,20"}, .turntable = "8"}, error);
  ASSERT_TRUE(turntable);
  ASSERT_EQ(turntable->views.size(), 8u);
  EXPECT_DOUBLE_EQ(turntable->views[1]->azimuth, 90.0);
  EXPECT_DOUBLE_EQ(turntable->views[7]->elevation, 20.0);
  EXPECT_EQ(turntable->paths.back(), "out-7.png");
  EXPECT_TRUE(turntable->oneDistance) << "a turntable keeps one camera distance";

  const auto frames = plan({.output = "f-%03d.png", .views = {"back"}, .frames = "1:2:11"}, error);
  ASSERT_TRUE(frames);
  EXPECT_EQ(frames->views.size(), 1u);
  EXPECT_EQ(frames->frameTimes.size(), 11u);
  EXPECT_EQ(frames->paths.back(), "f-010.png");
}

TEST(ImagePlan, NamesTheOptionAtFault) {
  const std::vector<std::pair<ImageOptions, std::string>> cases = {
      {{.size = "0x0"}, "--size"},
      {{.views = {"front", "sideways"}}, "--view"},
      {{.turntable = "-3"}, "--turntable"},
      {{.views = {"front", "back"}, .turntable = "3"}, "--turntable"},
      {{.frames = "0:1"}, "--frames"},
      {{.turntable = "2", .frames = "0:1:3"}, "--frames"},
      {{.output = "a%d%d.png", .turntable = "2"}, "--output"},
  };
  for (const auto& [options, option] : cases) {
    ImageOptionError error;
    EXPECT_FALSE(plan(options, error)) << option;
    EXPECT_EQ(error.option, option);
    EXPECT_FALSE(error.message.empty());
  }
}
