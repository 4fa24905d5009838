// figment-view --stats: a real engine's drape (a falling square) written as JSON and read
// back: the scene, the size, and per garment its DEF name with its report as
// io/DrapeReportJson.h writes it; a path that cannot be written is an error and no file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "io/DrapeReportJson.h"
#include "nodes/cloth/ClothEngine.h"
#include "sim/drape/DrapeReport.h"
#include "support/FallingSquare.h"
#include "support/TempDir.h"
#include "viewer/StatsJson.h"

using namespace figment;

namespace {

TEST(StatsJson, WritesEachEnginesNameAndReport) {
  const test::FallingSquare square(0.01);
  ASSERT_TRUE(square.read());
  square.drape();
  ASSERT_GT(square.engine().lastRun().run.iterations, 0);
  const test::TempDir dir;
  const std::string path = (dir.path() / "stats.json").string();
  ASSERT_EQ(viewer::writeStatsJson(path, "square.iv", {&square.engine()}, {}, 0.25, {320, 240}), "");
  const nlohmann::json stats = nlohmann::json::parse(std::ifstream(path));
  EXPECT_EQ(stats["scene"], "square.iv");
  EXPECT_EQ(stats["size"], nlohmann::json::array({320, 240}));
  EXPECT_EQ(stats["render_wall_s"], 0.25);
  ASSERT_EQ(stats["garments"].size(), 1u);
  nlohmann::json garment = stats["garments"][0];
  EXPECT_EQ(garment["name"], "Drape");
  EXPECT_EQ(garment["iterations"], square.engine().lastRun().run.iterations);
  EXPECT_FALSE(garment.contains("fit"));  // no fits given
  garment.erase("name");
  EXPECT_EQ(garment, nlohmann::json::parse(drapeReportJson(square.engine().lastRun())));
}

TEST(StatsJson, AnUnwritablePathIsAnErrorAndNoFile) {
  const test::FallingSquare square(0.01);
  ASSERT_TRUE(square.read());
  square.drape();
  const test::TempDir dir;
  dir.file("blocker", "a file where the folder would be\n");
  const std::string path = (dir.path() / "blocker" / "stats.json").string();  // its folder is a file
  EXPECT_NE(viewer::writeStatsJson(path, "square.iv", {&square.engine()}, {}, 0.0, {10, 10}), "");
  EXPECT_FALSE(std::filesystem::exists(path));
}

}  // namespace
