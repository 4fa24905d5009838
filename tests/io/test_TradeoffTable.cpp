// The study's front as a file: read back row by row with where it came from; a damaged
// table is an error naming file and line.
#include <gtest/gtest.h>

#include <stdexcept>

#include "io/TradeoffTable.h"
#include "support/TempDir.h"

using namespace figment;
using figment::test::TempDir;

namespace {
const char* kHeader = "method,body,progressive,resolution,garments,worst_mean_dev_pct_height,total_median_wall_s\n";

std::string expectError(const std::string& path) {
  try {
    readTradeoffTable(path);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  ADD_FAILURE() << path << " read without an error";
  return "";
}
}  // namespace

TEST(TradeoffTable, ReadsBackEveryRowAndItsSource) {
  const TempDir dir;
  const std::string path = dir.file("table.csv", std::string(kHeader) +
                                                     "implicit+penalty:0.05,volumes,off,1,3,1.2,0.5\n"
                                                     "implicit:0.05,triangles,0:3000,1,3,0.6,0.9\n"
                                                     "heun:1.5e-4:clamp:30,triangles,off,1,3,0.05,20\n");
  const MethodTable table = readTradeoffTable(path);
  EXPECT_EQ(table.source, path);
  const std::vector<MeasuredConfiguration>& rows = table.configurations;
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].method, "implicit+penalty:0.05");
  EXPECT_EQ(rows[1].body, "triangles");
  EXPECT_EQ(rows[1].progressive, "0:3000");
  EXPECT_EQ(rows[1].garments, 3);
  EXPECT_DOUBLE_EQ(rows[1].worstMeanDeviation, 0.6);
  EXPECT_DOUBLE_EQ(rows[2].totalWall, 20.0);
}

TEST(TradeoffTable, ADamagedTableIsAnErrorNamingFileAndLine) {
  const TempDir dir;
  EXPECT_NE(expectError(dir.file("a.csv", "scene,method\n")).find("a.csv: not a tradeoff table"), std::string::npos);
  EXPECT_NE(expectError(dir.file("b.csv", std::string(kHeader) + "implicit:0.05,volumes,off,1,3,abc,0.5\n"))
                .find("b.csv:2: \"abc\" is not a number"),
            std::string::npos);
  EXPECT_NE(expectError(dir.file("c.csv", std::string(kHeader) + "implicit:0.05,volumes,off,1,3\n")).find("c.csv:2:"),
            std::string::npos);
  EXPECT_NE(expectError(dir.file("d.csv", std::string(kHeader) + "verlet:0.05,volumes,off,1,3,0.1,0.5\n"))
                .find("d.csv:2: method \"verlet:0.05\": no integrator verlet"),
            std::string::npos);
  EXPECT_NE(expectError((dir.path() / "missing.csv").string()).find("missing.csv: cannot be read"), std::string::npos);
}
