// figment-view's --size and --view values.

#include <gtest/gtest.h>

#include "viewer/ViewOptions.h"

using namespace figment::viewer;

TEST(ViewOptions, ParsesSizes) {
  ASSERT_TRUE(parseImageSize("800x600"));
  EXPECT_EQ(parseImageSize("800x600")->width, 800);
  EXPECT_EQ(parseImageSize("800x600")->height, 600);
  EXPECT_EQ(parseImageSize("1X2")->height, 2);
  for (const char* bad :
       {"", "800", "800x", "x600", "0x600", "800x0", "-800x600", "800x600x3", "abc", "99999x10", "800 x 600", "1.5x2"})
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

TEST(ViewOptions, ParsesTurntableCounts) {
  EXPECT_EQ(parseTurntableCount("1"), 1);
  EXPECT_EQ(parseTurntableCount("8"), 8);
  EXPECT_EQ(parseTurntableCount("3600"), 3600);
  for (const char* bad : {"", "0", "-1", "+8", "8.0", "8 ", " 8", "x", "3601", "99999999999999999999", "8x"})
    EXPECT_FALSE(parseTurntableCount(bad)) << bad;
}

TEST(ViewOptions, ATurntableGoesAroundFromItsStart) {
  const std::vector<ViewDirection> four = turntableViews(4, std::nullopt);
  ASSERT_EQ(four.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    EXPECT_DOUBLE_EQ(four[i].azimuth, 90.0 * i);
    EXPECT_DOUBLE_EQ(four[i].elevation, 0.0);
  }
  const std::vector<ViewDirection> three = turntableViews(3, ViewDirection{30.0, 10.0});
  ASSERT_EQ(three.size(), 3u);
  EXPECT_DOUBLE_EQ(three[1].azimuth, 150.0);
  EXPECT_DOUBLE_EQ(three[2].azimuth, 270.0);
  EXPECT_DOUBLE_EQ(three[2].elevation, 10.0);
}

TEST(ViewOptions, ParsesFrameTimes) {
  const auto times = parseFrameTimes("0.5:2.5:5");
  ASSERT_TRUE(times);
  EXPECT_EQ(*times, (std::vector<double>{0.5, 1.0, 1.5, 2.0, 2.5}));
  EXPECT_EQ(*parseFrameTimes("2:2:1"), std::vector<double>{2.0});
  EXPECT_EQ(*parseFrameTimes("1:3:1"), std::vector<double>{1.0});  // one frame: the first time
  EXPECT_EQ(parseFrameTimes(".25:1:4")->back(), 1.0);
  EXPECT_EQ(parseFrameTimes("0:1:10000")->size(), 10000u);
}

TEST(ViewOptions, RejectsBadFrameTimes) {
  for (const char* bad : {"", "0:1", "0:1:", ":1:3", "0::3", "0:1:3:4", "1:0:3", "-1:1:3", "0:1:0", "0:1:-2", "0:1:1.5",
                          "0:1:10001", "a:1:3", "0:inf:3", "0:nan:3", "0:1e3:3", "0:2000000:3", "0;1;3", "0:1:3 "})
    EXPECT_FALSE(parseFrameTimes(bad)) << bad;
}
