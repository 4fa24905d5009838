// figment-view's progress bar: its line, and silence when the stream is no terminal.

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "viewer/ProgressBar.h"

using namespace figment::viewer;

TEST(ProgressBar, FillsInProportionToSimulatedTime) {
  const std::string half = progressBarLine("ClothEngine 'Drape'", 2.5, 5.0, 1.25, 10);
  EXPECT_EQ(half.rfind("ClothEngine 'Drape' [#####.....]", 0), 0u) << half;
  EXPECT_NE(half.find("2.5 / 5 s simulated, 1.2 s"), std::string::npos) << half;
  EXPECT_NE(progressBarLine("e", 0.0, 5.0, 0.0, 4).find("[....]"), std::string::npos);
  EXPECT_NE(progressBarLine("e", 9.0, 5.0, 0.0, 4).find("[####]"), std::string::npos);  // held within the bar
  EXPECT_NE(progressBarLine("e", 1.0, 0.0, 0.0, 4).find("[....]"), std::string::npos);  // no bound: nothing filled
}

TEST(ProgressBar, WritesNothingWhereTheStreamIsNoTerminal) {
  std::FILE* file = std::tmpfile();
  ASSERT_NE(file, nullptr);
  {
    ProgressBar bar(file);
    EXPECT_FALSE(bar.shown());
    bar.draw("ClothEngine [###...]");
    bar.clear();
  }
  EXPECT_EQ(std::ftell(file), 0L);
  std::fclose(file);
}
