// figment-sew (tools/sew.cpp): a pattern sewn on a body and draped, written with its
// figures; bad input is one line naming the file and what is wrong, exit status 1 and no
// file. Run from the build's bin folder, as a user runs it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "support/ProgramRun.h"
#include "support/TempDir.h"

namespace {

using figment::test::quote;

const std::string kSew = std::string(FIGMENT_BINARY_DIR) + "/bin/figment-sew";
const std::string kPencil = std::string(FIGMENT_SOURCE_DIR) + "/tests/io/data/patterns/pencil-f-46_specification.json";

figment::test::ProgramResult sew(const figment::test::TempDir& dir, const std::string& arguments) {
  return figment::test::runProgram(kSew, arguments, dir.path(), dir.path() / "cache");
}

int lines(const std::string& text) {
  int n = 0;
  for (char c : text) n += c == '\n';
  return n;
}

}  // namespace

TEST(SewTool, SewsAPatternOnTheDefaultBodyAndSaysWhatTheDrapeDid) {
  const figment::test::TempDir dir;
  const std::filesystem::path out = dir.path() / "pencil.glb", stats = dir.path() / "pencil.json";
  const auto result = sew(dir, quote(kPencil) + " -o " + quote(out.string()) + " --stats " + quote(stats.string()));
  ASSERT_EQ(result.status, 0) << result.err;
  ASSERT_TRUE(std::filesystem::exists(out));
  const nlohmann::json figures = nlohmann::json::parse(std::ifstream(stats));
  for (const char* key : {"at_rest", "seam_gap_max_m", "inside_nodes", "steps", "wall_s", "drape"})
    EXPECT_TRUE(figures.contains(key)) << key;
  // The drape's report as figment-view --stats writes it (io/DrapeReportJson.h).
  EXPECT_GT(figures["drape"]["verdict"]["max_edge_stretch"].get<double>(), 0.9);
  EXPECT_EQ(figures["drape"]["iterations"], figures["drape_steps"]);
  EXPECT_EQ(figures["drape"]["at_rest"], figures["at_rest"]);
  // The report's wall time is the whole drape's, setting up included (it said 0 before).
  EXPECT_GE(figures["drape"]["wall_s"].get<double>(), figures["wall_s"].get<double>());
  EXPECT_GT(figures["wall_s"].get<double>(), 0.0);
  // What stderr says agrees with the figures: a clean drape prints nothing.
  EXPECT_EQ(figures["clean"].get<bool>(), result.err.empty()) << result.err;
  EXPECT_GT(figures["steps"].get<int>(), 0);
  // Sewn: each closed seam's two sides became one node.
  EXPECT_LT(figures["sewn_nodes"].get<int>(), figures["nodes"].get<int>());
}

TEST(SewTool, ABadPatternIsOneLineNamingTheFileAndNoFile) {
  const figment::test::TempDir dir;
  std::string text;
  {
    std::ifstream in(kPencil);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  const std::string circle = "\"type\": \"circle\"";
  ASSERT_NE(text.find(circle), std::string::npos);  // the control: the file has a circle to break
  text.replace(text.find(circle), circle.size(), "\"type\": \"spline\"");
  const std::filesystem::path bad = dir.path() / "bad.json", out = dir.path() / "bad.obj";
  std::ofstream(bad) << text;
  const auto result = sew(dir, quote(bad.string()) + " -o " + quote(out.string()) + " --stats " +
                                   quote((dir.path() / "bad-stats.json").string()));
  EXPECT_EQ(result.status, 1);
  EXPECT_EQ(lines(result.err), 1) << result.err;
  EXPECT_NE(result.err.find(bad.string()), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("spline"), std::string::npos) << result.err;
  EXPECT_FALSE(std::filesystem::exists(out));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "bad-stats.json"));
}

TEST(SewTool, AnOutputItCannotWriteIsOneLineBeforeAnyWork) {
  const figment::test::TempDir dir;
  const auto result = sew(dir, quote(kPencil) + " -o " + quote((dir.path() / "skirt.stl").string()));
  EXPECT_EQ(result.status, 1);
  EXPECT_EQ(lines(result.err), 1) << result.err;
  EXPECT_NE(result.err.find("skirt.stl: not .obj, .glb or .gltf"), std::string::npos) << result.err;
}

TEST(SewTool, AMissingPatternIsOneLine) {
  const figment::test::TempDir dir;
  const auto result =
      sew(dir, quote((dir.path() / "none.json").string()) + " -o " + quote((dir.path() / "x.obj").string()));
  EXPECT_EQ(result.status, 1);
  EXPECT_EQ(lines(result.err), 1) << result.err;
  EXPECT_NE(result.err.find("none.json"), std::string::npos) << result.err;
}
