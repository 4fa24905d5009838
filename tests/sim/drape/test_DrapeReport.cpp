// A report's verdict: the garment's warning and the run's ending in one line, "" when clean.
#include <gtest/gtest.h>

#include "sim/drape/DrapeReport.h"

using namespace figment;

TEST(DrapeReport, TheVerdictJoinsTheGarmentsWarningAndTheRunsEnding) {
  DrapeReport report;
  report.maxTime = 5.0;
  report.run.atRest = true;
  report.run.maxStretch = 1.05;
  EXPECT_EQ(verdictOf(report), "");
  report.garmentWarning = "12 nodes start inside the body";
  EXPECT_EQ(verdictOf(report), "12 nodes start inside the body");
  report.run.atRest = false;
  report.run.maxSpeed = 0.31;
  EXPECT_EQ(verdictOf(report), "12 nodes start inside the body; not at rest after maxTime 5 s (max speed 0.31 m/s)");
  report.garmentWarning.clear();
  report.run.maxStretch = 2.02;
  EXPECT_EQ(
      verdictOf(report),
      "not at rest after maxTime 5 s (max speed 0.31 m/s); torn: an edge at 2.02 times its rest length (bound 1.5)");
}
