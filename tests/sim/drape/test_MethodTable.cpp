// The measured front as data: the fastest configuration within a tolerance among those
// allowed, a row's label, and a progressive schedule as the table spells it.
#include <gtest/gtest.h>

#include <stdexcept>

#include "sim/drape/MethodTable.h"

using namespace figment;

namespace {
std::vector<MeasuredConfiguration> threeRows() {
  return {{"implicit+penalty:0.05", "volumes", "off", 1.0, 3, 1.2, 0.5},
          {"implicit:0.05", "triangles", "0:3000", 1.0, 3, 0.6, 0.9},
          {"heun:1.5e-4:clamp:30", "triangles", "off", 1.0, 3, 0.05, 20.0}};
}
}  // namespace

TEST(MethodTable, PicksTheFastestWithinTheToleranceAmongThoseAllowed) {
  const std::vector<MeasuredConfiguration> table = threeRows();
  const auto any = [](const MeasuredConfiguration&) { return true; };
  EXPECT_EQ(fastestWithin(table, 2.0, any)->method, "implicit+penalty:0.05");
  EXPECT_EQ(fastestWithin(table, 1.0, any)->method, "implicit:0.05");
  EXPECT_EQ(fastestWithin(table, 0.6, any)->method, "implicit:0.05");  // the bound itself is within
  EXPECT_EQ(fastestWithin(table, 0.1, any)->method, "heun:1.5e-4:clamp:30");
  EXPECT_FALSE(fastestWithin(table, 0.01, any));
  const auto noTriangles = [](const MeasuredConfiguration& c) { return c.body != "triangles"; };
  EXPECT_FALSE(fastestWithin(table, 1.0, noTriangles));
  EXPECT_EQ(fastestWithin(table, 2.0, noTriangles)->method, "implicit+penalty:0.05");
}

TEST(MethodTable, ARowsLabelNamesMethodBodyScheduleAndAResampling) {
  MeasuredConfiguration c = threeRows()[1];
  EXPECT_EQ(c.label(), "implicit:0.05, triangles, progressive 0:3000");
  c.resolution = 2.0;
  EXPECT_EQ(c.label(), "implicit:0.05, triangles, progressive 0:3000, sections x2.000000");
}

TEST(MethodTable, SchedulesAsTheTableSpellsThem) {
  const ScheduleText s = parseScheduleText("0.5:1200");
  EXPECT_DOUBLE_EQ(s.beginShare, 0.5);
  EXPECT_DOUBLE_EQ(s.rate, 1200.0);
  for (const char* bad : {"0.5", "1.5:10", "0:-1", "0:10x", "off"})
    EXPECT_THROW(parseScheduleText(bad), std::invalid_argument) << bad;
}
