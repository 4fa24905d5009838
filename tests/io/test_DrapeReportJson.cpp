// A drape's report as JSON (io/DrapeReportJson.h): one garment's drape, as plain values,
// written and read back field by field; a tolerance's pick and a progressive drape's
// levels only when there are some.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "io/DrapeReportJson.h"

using namespace figment;

namespace {

DrapeReport dressReport() {
  DrapeReport report;
  report.triangles = 1200;
  report.run.iterations = 80;
  report.run.simulatedTime = 4.0;
  report.run.atRest = true;
  report.run.maxStretch = 1.05;
  report.method.integrator = Integrator::Implicit;
  report.method.timeStep = 0.05;
  report.method.maxTimeStep = 0.4;
  report.method.limiter = AccelerationLimiter::None;
  report.method.limit = 3.0;  // not in force: written as 0
  report.body = {"mannequin", {{"capsules", 12}}};
  report.wallSeconds = 0.125;
  return report;
}

TEST(DrapeReportJson, WritesTheRunMethodAndBody) {
  const nlohmann::json json = nlohmann::json::parse(drapeReportJson(dressReport()));
  EXPECT_EQ(json["triangles"], 1200);
  EXPECT_EQ(json["iterations"], 80);
  EXPECT_EQ(json["simulated_s"], 4.0);
  EXPECT_EQ(json["wall_s"], 0.125);
  EXPECT_EQ(json["at_rest"], true);
  EXPECT_EQ(json["cached"], false);
  EXPECT_EQ(json["verdict"]["clean"], true);
  EXPECT_EQ(json["verdict"]["max_edge_stretch"], 1.05);
  EXPECT_EQ(json["method"]["integrator"], "IMPLICIT");
  EXPECT_EQ(json["method"]["time_step_s"], 0.05);
  EXPECT_EQ(json["method"]["max_time_step_s"], 0.4);
  EXPECT_EQ(json["method"]["acceleration_limit_g"], 0.0);
  EXPECT_EQ(json["body"]["kind"], "mannequin");
  EXPECT_EQ(json["body"]["capsules"], 12);
  EXPECT_FALSE(json.contains("progressive"));          // no progressive script
  EXPECT_FALSE(json.contains("picked"));               // no tolerance
  EXPECT_FALSE(json.contains("started_over_layers"));  // nothing beneath
}

TEST(DrapeReportJson, AGarmentPutOnOverAnotherSaysHowManyNodesStartedOverIt) {
  DrapeReport report = dressReport();
  report.startedOverLayers = 313;
  EXPECT_EQ(nlohmann::json::parse(drapeReportJson(report))["started_over_layers"], 313);
}

TEST(DrapeReportJson, AVerdictIsNotClean) {
  DrapeReport report = dressReport();
  report.verdict = "not at rest after maxTime 5 s (max speed 0.31 m/s)";
  const nlohmann::json json = nlohmann::json::parse(drapeReportJson(report));
  EXPECT_EQ(json["verdict"]["clean"], false);
  EXPECT_EQ(json["verdict"]["text"], report.verdict);
}

TEST(DrapeReportJson, AProgressiveDrapeSaysItsLevels) {
  DrapeReport report = dressReport();
  report.levels = 5;
  report.level = 5;
  report.sections = 900;
  const nlohmann::json json = nlohmann::json::parse(drapeReportJson(report));
  EXPECT_EQ(json["progressive"]["levels"], 5);
  EXPECT_EQ(json["progressive"]["sections"], 900);
}

TEST(DrapeReportJson, AToleranceSaysWhatItPicked) {
  DrapeReport report = dressReport();
  report.picked = "implicit 1/20 s, capsules";
  report.pickedDeviation = 0.8;
  const nlohmann::json json = nlohmann::json::parse(drapeReportJson(report));
  EXPECT_EQ(json["picked"]["configuration"], report.picked);
  EXPECT_EQ(json["picked"]["measured_worst_mean_dev_pct_height"], 0.8);
}

}  // namespace
