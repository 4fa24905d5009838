// figment-view --stats: one garment's drape, as plain values, written as JSON and read back
// field by field; a path that cannot be written is an error and no file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/TempDir.h"
#include "viewer/StatsJson.h"

using namespace figment;

namespace {

session::EngineDrape dressDrape() {
  session::EngineDrape drape;
  drape.name = "Dress";
  DrapeReport& report = drape.report;
  report.triangles = 1200;
  report.run.iterations = 80;
  report.run.simulatedTime = 4.0;
  report.run.atRest = true;
  report.run.maxStretch = 1.05;
  report.method.integrator = Integrator::Implicit;
  report.method.timeStep = 0.05;
  report.method.limiter = AccelerationLimiter::None;
  report.method.limit = 3.0;  // not in force: written as 0
  report.body = {"mannequin", {{"capsules", 12}}};
  return drape;
}

TEST(StatsJson, WritesEachGarmentsRunMethodAndBody) {
  const test::TempDir dir;
  const std::string path = (dir.path() / "stats.json").string();
  ASSERT_EQ(viewer::writeStatsJson(path, "dress.iv", {dressDrape()}, {}, 0.25, {320, 240}), "");
  const nlohmann::json stats = nlohmann::json::parse(std::ifstream(path));
  EXPECT_EQ(stats["scene"], "dress.iv");
  EXPECT_EQ(stats["size"], nlohmann::json::array({320, 240}));
  EXPECT_EQ(stats["render_wall_s"], 0.25);
  ASSERT_EQ(stats["garments"].size(), 1u);
  const nlohmann::json& garment = stats["garments"][0];
  EXPECT_EQ(garment["name"], "Dress");
  EXPECT_EQ(garment["triangles"], 1200);
  EXPECT_EQ(garment["at_rest"], true);
  EXPECT_EQ(garment["verdict"]["clean"], true);
  EXPECT_EQ(garment["verdict"]["max_edge_stretch"], 1.05);
  EXPECT_EQ(garment["method"]["integrator"], "IMPLICIT");
  EXPECT_EQ(garment["method"]["time_step_s"], 0.05);
  EXPECT_EQ(garment["method"]["acceleration_limit_g"], 0.0);
  EXPECT_EQ(garment["body"]["kind"], "mannequin");
  EXPECT_EQ(garment["body"]["capsules"], 12);
  EXPECT_FALSE(garment.contains("progressive"));  // no progressive script
  EXPECT_FALSE(garment.contains("picked"));       // no tolerance
}

TEST(StatsJson, AProgressiveDrapeSaysItsLevels) {
  const test::TempDir dir;
  const std::string path = (dir.path() / "stats.json").string();
  session::EngineDrape drape = dressDrape();
  drape.report.levels = 5;
  drape.report.level = 5;
  drape.report.sections = 900;
  ASSERT_EQ(viewer::writeStatsJson(path, "dress.iv", {drape}, {}, 0.0, {10, 10}), "");
  const nlohmann::json garment = nlohmann::json::parse(std::ifstream(path))["garments"][0];
  EXPECT_EQ(garment["progressive"]["levels"], 5);
  EXPECT_EQ(garment["progressive"]["sections"], 900);
}

TEST(StatsJson, AnUnwritablePathIsAnErrorAndNoFile) {
  const test::TempDir dir;
  dir.file("blocker", "a file where the folder would be\n");
  const std::string path = (dir.path() / "blocker" / "stats.json").string();  // its folder is a file
  EXPECT_NE(viewer::writeStatsJson(path, "dress.iv", {dressDrape()}, {}, 0.0, {10, 10}), "");
  EXPECT_FALSE(std::filesystem::exists(path));
}

}  // namespace
