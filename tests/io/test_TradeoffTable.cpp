// The study's front as a table: read back, the fastest within a tolerance picked, its
// method spelled onto the parameters; a damaged table is an error naming file and line.
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

TEST(TradeoffTable, ReadsBackAndPicksTheFastestWithinTheTolerance) {
  const TempDir dir;
  const std::string path = dir.file("table.csv", std::string(kHeader) +
                                                     "implicit+penalty:0.05,volumes,off,1,3,1.2,0.5\n"
                                                     "implicit:0.05,triangles,0:3000,1,3,0.6,0.9\n"
                                                     "heun:1.5e-4:clamp:30,triangles,off,1,3,0.05,20\n");
  const std::vector<MeasuredConfiguration> table = readTradeoffTable(path);
  ASSERT_EQ(table.size(), 3u);
  EXPECT_EQ(table[1].progressive, "0:3000");
  EXPECT_DOUBLE_EQ(table[1].worstMeanDeviation, 0.6);
  const auto any = [](const MeasuredConfiguration&) { return true; };
  EXPECT_EQ(fastestWithin(table, 2.0, any)->method, "implicit+penalty:0.05");
  EXPECT_EQ(fastestWithin(table, 1.0, any)->method, "implicit:0.05");
  EXPECT_EQ(fastestWithin(table, 0.1, any)->method, "heun:1.5e-4:clamp:30");
  EXPECT_FALSE(fastestWithin(table, 0.01, any));
  const auto noTriangles = [](const MeasuredConfiguration& c) { return c.body != "triangles"; };
  EXPECT_FALSE(fastestWithin(table, 1.0, noTriangles));
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

TEST(TradeoffTable, MethodsAndSchedulesAsTheStudySpellsThem) {
  ClothParameters p;
  applyMethod("implicit+penalty:0.02", p);
  EXPECT_EQ(p.integrator, Integrator::Implicit);
  EXPECT_EQ(p.implicitSolver.contacts, ContactModel::Penalty);
  EXPECT_DOUBLE_EQ(p.timeStep, 0.02);
  EXPECT_EQ(p.accelerationLimiter, AccelerationLimiter::None);
  applyMethod("HEUN:1.5e-4:Clamp:30", p);
  EXPECT_EQ(p.integrator, Integrator::Heun);
  EXPECT_EQ(p.accelerationLimiter, AccelerationLimiter::Clamp);
  EXPECT_DOUBLE_EQ(p.accelerationLimit, 30.0);
  for (const char* bad : {"heun", "heun:0", "heun:x", "implicit+glue:0.05", "heun:1e-4:clamp", "heun:1e-4:soft:3"})
    EXPECT_THROW(applyMethod(bad, p), std::invalid_argument) << bad;
  const ScheduleText s = parseScheduleText("0.5:1200");
  EXPECT_DOUBLE_EQ(s.beginShare, 0.5);
  EXPECT_DOUBLE_EQ(s.rate, 1200.0);
  for (const char* bad : {"0.5", "1.5:10", "0:-1", "0:10x", "off"})
    EXPECT_THROW(parseScheduleText(bad), std::invalid_argument) << bad;
}
