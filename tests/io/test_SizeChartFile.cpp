// The size chart's file: the shipped chart reads as twelve sizes (docs/sizes.md); a bad line
// is refused naming the file, the line and the field.
#include <gtest/gtest.h>

#include <fstream>

#include "io/SizeChartFile.h"
#include "support/IoTestSupport.h"

using namespace figment;
using figment::test::TempDir;

namespace {

std::string writeChart(const TempDir& dir, const std::string& text) {
  const std::string path = (dir.path() / "chart.txt").string();
  std::ofstream(path) << text;
  return path;
}

std::string errorOf(const std::string& path) {
  try {
    readSizeChart(path);
  } catch (const std::runtime_error& error) {
    return error.what();
  }
  return "";
}

}  // namespace

TEST(SizeChartFile, TheShippedChartRunsToDob54AndHaka62) {
  const SizeChart chart = readSizeChart(defaultSizeChartPath());
  ASSERT_EQ(chart.sizes(Sex::Female).size(), 12u);
  ASSERT_EQ(chart.sizes(Sex::Male).size(), 10u);
  // issue 43's ends: DOB 54 (7XL) bust 1.28, waist 1.12, hips 1.32 m; HAKA 62 (6XL) chest 1.24 m
  const ChartSize& dob54 = chart.sizes(Sex::Female).back();
  EXPECT_EQ(dob54.number, "54");
  EXPECT_EQ(dob54.name, "7XL");
  EXPECT_DOUBLE_EQ(dob54.bust, 1.28);
  EXPECT_DOUBLE_EQ(dob54.waist, 1.12);
  EXPECT_DOUBLE_EQ(dob54.hip, 1.32);
  const ChartSize& haka62 = chart.sizes(Sex::Male).back();
  EXPECT_EQ(haka62.number, "62");
  EXPECT_DOUBLE_EQ(haka62.bust, 1.24);
  // the 6 cm steps from DOB 46 up in bust and waist
  const ChartSize& dob46 = chart.sizes(Sex::Female)[chart.find(Sex::Female, "46")];
  const ChartSize& dob48 = chart.sizes(Sex::Female)[chart.find(Sex::Female, "48")];
  EXPECT_NEAR(dob48.bust - dob46.bust, 0.06, 1e-12);
  EXPECT_NEAR(dob48.waist - dob46.waist, 0.06, 1e-12);
  const ChartSize& m = chart.sizes(Sex::Female)[chart.find(Sex::Female, "M")];
  EXPECT_EQ(m.number, "38");
  EXPECT_DOUBLE_EQ(m.bust, 0.88);
  EXPECT_DOUBLE_EQ(m.waist, 0.72);
  EXPECT_DOUBLE_EQ(m.hip, 0.96);
  EXPECT_EQ(chart.sizes(Sex::Male)[chart.find(Sex::Male, "M")].number, "48");
}

TEST(SizeChartFile, BadLinesAreNamed) {
  const TempDir dir;
  EXPECT_EQ(errorOf(writeChart(dir, "# sizes\nfemale M 38 1.68 0.88 0.72\n")),
            dir.path().string() + "/chart.txt:2: no hip");
  EXPECT_EQ(errorOf(writeChart(dir, "female M 38 1.68 0.88 x72 0.96\n")),
            dir.path().string() + "/chart.txt:1: waist 'x72' is not a number");
  EXPECT_EQ(errorOf(writeChart(dir, "woman M 38 1.68 0.88 0.72 0.96\n")),
            dir.path().string() + "/chart.txt:1: sex 'woman' is not female or male");
  EXPECT_EQ(errorOf(writeChart(dir, "female M 38 1.68 0.88 0.72 0.96 7\n")),
            dir.path().string() + "/chart.txt:1: unexpected '7'");
  EXPECT_EQ(errorOf(writeChart(dir, "female M 38 1.68 0.88 0.72 0.96\nfemale L 40 1.68 0.92 0.70 1.0\n")),
            dir.path().string() + "/chart.txt: size female L is not larger than M in every girth");
  EXPECT_EQ(errorOf((dir.path() / "none.txt").string()), (dir.path() / "none.txt").string() + ": cannot be opened");
}
