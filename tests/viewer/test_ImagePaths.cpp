// figment-view's output names for several images.

#include <gtest/gtest.h>

#include <algorithm>

#include "viewer/ImagePaths.h"

using figment::viewer::imagePaths;
using Paths = std::vector<std::string>;

TEST(ImagePaths, OneImageIsTheNameGiven) {
  EXPECT_EQ(*imagePaths("out.png", 1), Paths{"out.png"});
  EXPECT_EQ(*imagePaths("dir.v2/out", 1), Paths{"dir.v2/out"});
}

TEST(ImagePaths, SeveralAreNumberedBeforeTheExtensionAndSort) {
  EXPECT_EQ(*imagePaths("out.png", 3), (Paths{"out-0.png", "out-1.png", "out-2.png"}));
  EXPECT_EQ(*imagePaths("a/b.c/out", 2), (Paths{"a/b.c/out-0", "a/b.c/out-1"}));
  const Paths forty = *imagePaths("wind.png", 40);
  ASSERT_EQ(forty.size(), 40u);
  EXPECT_EQ(forty.front(), "wind-00.png");
  EXPECT_EQ(forty[9], "wind-09.png");
  EXPECT_EQ(forty.back(), "wind-39.png");
  EXPECT_TRUE(std::is_sorted(forty.begin(), forty.end()));
  EXPECT_EQ(imagePaths("x.png", 10)->back(), "x-9.png");
  EXPECT_EQ(imagePaths("x.png", 11)->back(), "x-10.png");
}

TEST(ImagePaths, APrintfNumberTakesTheIndex) {
  EXPECT_EQ(*imagePaths("frame-%d.png", 2), (Paths{"frame-0.png", "frame-1.png"}));
  EXPECT_EQ(*imagePaths("frame-%03d.png", 2), (Paths{"frame-000.png", "frame-001.png"}));
  EXPECT_EQ(*imagePaths("f%d.png", 1), Paths{"f0.png"});
  EXPECT_EQ(*imagePaths("50%.png", 2), (Paths{"50%-0.png", "50%-1.png"}));  // no number: left alone
}

TEST(ImagePaths, RefusesNumbersItCannotUse) {
  for (const char* bad : {"a%d%d.png", "a%5d.png", "a%0d.png", "a%010d.png", "%d/%d.png"})
    EXPECT_FALSE(imagePaths(bad, 2)) << bad;
}
