// A study's CSV is written whole or not at all: its path on stdout when written, one line on
// stderr and no file when its rows fail.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "bench/CsvFile.h"
#include "support/TempDir.h"

using namespace figment::bench;

namespace {

std::string contents(const std::string& path) {
  std::stringstream text;
  text << std::ifstream(path).rdbuf();
  return text.str();
}

TEST(CsvFile, WritesTheRowsAndPrintsThePath) {
  const figment::test::TempDir dir;
  const std::string path = (dir.path() / "study.csv").string();
  testing::internal::CaptureStdout();
  EXPECT_TRUE(writeCsv(path, [](std::ostream& csv) {
    csv << "a,b\n1,2\n";
    return std::string();
  }));
  EXPECT_EQ(testing::internal::GetCapturedStdout(), path + "\n");
  EXPECT_EQ(contents(path), "a,b\n1,2\n");
}

TEST(CsvFile, AFailedFillLeavesNoFileAndOneLine) {
  const figment::test::TempDir dir;
  const std::string path = (dir.path() / "study.csv").string();
  testing::internal::CaptureStderr();
  EXPECT_FALSE(writeCsv(path, [](std::ostream& csv) {
    csv << "a,b\n";
    return std::string("scene.iv: cannot drape");
  }));
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "figment-bench: scene.iv: cannot drape\n");
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));  // no temporary left either
}

TEST(CsvFile, NoPlotScriptMeansNoChart) {
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  chartCsv("", "study.csv", "study.png");
  chartCsv("/no/such/plot.py", "study.csv", "study.png");
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
  EXPECT_EQ(testing::internal::GetCapturedStdout(), "");
}

}  // namespace
