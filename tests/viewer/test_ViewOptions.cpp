// figment-view's --size and --view values.

#include "viewer/ViewOptions.h"

#include <gtest/gtest.h>

using namespace figment::viewer;

TEST(ViewOptions, ParsesSizes) {
  ASSERT_TRUE(parseImageSize("800x600"));
  EXPECT_EQ(parseImageSize("800x600")->width, 800);
  EXPECT_EQ(parseImageSize("800x600")->height, 600);
  EXPECT_EQ(parseImageSize("1X2")->height, 2);
  for (const char* bad : {"", "800", "800x", "x600", "0x600", "800x0", "-800x600", "800x600x3", "abc", "99999x10",
                          "800 x 600", "1.5x2"})
    EXPECT_FALSE(parseImageSize(bad)) << bad;
}

TEST(ViewOptions, ParsesNamedViews) {
  const auto angles = [](const char* text) {
    const auto v = parseViewDirection(text);
    return v ? std::make_pair(v->azimuth, v->elevation) : std::make_pair(-1.0, -1.0);
  };
  EXPECT_EQ(angles("front"), std::make_pair(0.0, 0.0));
  EXPECT_EQ(angles("right"), std::make_pair(90.0, 0.0));
  EXPECT_EQ(angles("back"), std::make_pair(180.0, 0.0));
  EXPECT_EQ(angles("left"), std::make_pair(270.0, 0.0));
  EXPECT_EQ(angles("30,15"), std::make_pair(30.0, 15.0));
  EXPECT_EQ(angles("-45.5, -10"), std::make_pair(-45.5, -10.0));
  EXPECT_EQ(angles("+.5,1."), std::make_pair(0.5, 1.0));
}

TEST(ViewOptions, RejectsBadViews) {
  for (const char* bad : {"", "up", "Front", "30", "30,", ",15", "30,90", "30,-90", "30,95", "a,b", "30;15", "1,2,3",
                          "1e3,0", "inf,0", "nan,0", "--30,0", "3 0,0", ".,0", "+-1,0"})
    EXPECT_FALSE(parseViewDirection(bad)) << bad;
}

TEST(ViewOptions, RejectsAnAngleTooLargeForADoubleWithoutThrowing) {
  // Found by fuzzing: a 400-digit azimuth made std::stod throw past main().
  const std::string huge(400, '9');
  EXPECT_NO_THROW(EXPECT_FALSE(parseViewDirection(huge + ",0")));
  EXPECT_NO_THROW(EXPECT_FALSE(parseViewDirection("0," + huge)));
  // A long fraction is no trouble: 0.999... reads as 1.
  ASSERT_TRUE(parseViewDirection("0." + huge + ",0"));
  EXPECT_NEAR(parseViewDirection("0." + huge + ",0")->azimuth, 1.0, 1e-12);
}
