// figment-view writing several images from one drape: repeated --view, --turntable,
// --frames of a time span, --wind-force, --list-nodes; each image whole or not at all,
// none left after an error.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "io/MeshImport.h"
#include "support/PngPixels.h"
#include "support/ProgramRun.h"
#include "support/TempDir.h"

namespace test_FigmentViewImages {

namespace fs = std::filesystem;

namespace {

using figment::test::quote;

// An image's pixels as bytes, for comparing pictures; empty when unreadable.
std::string pixels(const std::string& path) {
  const figment::test::Image image = figment::test::readPng(path);
  return std::string(image.rgb.begin(), image.rgb.end());
}

using ProcessResult = figment::test::ProgramResult;

class FigmentViewImages : public ::testing::Test {
 protected:
  std::string path(const std::string& name) const { return (dir_.path() / name).string(); }
  std::string write(const std::string& name, const std::string& text) const { return dir_.file(name, text); }
  // figment-view with `arguments` (shell words), its drape cache in this test's folder.
  ProcessResult run(const std::string& arguments) const {
    return figment::test::runProgram(FIGMENT_VIEW_EXECUTABLE, arguments, dir_.path(), path("cache"));
  }
  // The PNG files in the test's folder, by name.
  std::set<std::string> images() const {
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_.path()))
      if (entry.path().extension() == ".png") names.insert(entry.path().filename().string());
    return names;
  }
  // Each image's pixels differ from every other's.
  void expectAllDiffer(const std::vector<std::string>& names) const {
    for (const std::string& name : names) ASSERT_NE(pixels(path(name)), "") << name;
    for (size_t i = 0; i < names.size(); ++i)
      for (size_t j = i + 1; j < names.size(); ++j)
        EXPECT_NE(pixels(path(names[i])), pixels(path(names[j]))) << names[i] << " and " << names[j];
  }

  figment::test::TempDir dir_;
};

// A square of cloth falling from 1 m (Heun, 1 ms steps, `seconds` simulated) and a box to
// its right, so that views from opposite sides differ; `fields` go into its engine.
std::string fallingSquare(double seconds, const std::string& fields = "") {
  return "#Inventor V2.1 ascii\nSeparator {\n"
         "  Separator { Translation { translation 1 0.5 0 } Cube { width 0.3 height 0.6 depth 0.3 } }\n"
         "  Material { diffuseColor 0.1 0.3 0.8 }\n"
         "  Coordinate3 { point = DEF Drape ClothEngine {\n"
         "    restPoints [ -0.5 1 -0.5, 0.5 1 -0.5, 0.5 1 0.5, -0.5 1 0.5 ]\n"
         "    coordIndex [ 0 3 2 1 -1 ]  timeStep 0.001  maxTime " +
         std::to_string(seconds) + "\n    " + fields +
         "\n  } . positions }\n"
         "  DEF Layer ClothingLayer { coordIndex [ 0 3 2 1 -1 ] }\n"
         "}\n";
}

// One CSV row of --wind-force.
struct WindRow {
  double time, pressure, phase, fx, fy, fz, magnitude;
};

std::vector<WindRow> readWindCsv(const std::string& file, std::string& header) {
  std::ifstream in(file);
  std::getline(in, header);
  std::vector<WindRow> rows;
  for (std::string line; std::getline(in, line);) {
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream fields(line);
    std::string engine;
    WindRow r{};
    fields >> engine >> r.time >> r.pressure >> r.phase >> r.fx >> r.fy >> r.fz >> r.magnitude;
    EXPECT_TRUE(engine == "Drape" || engine == "WindDrape") << engine;
    rows.push_back(r);
  }
  return rows;
}

}  // namespace

TEST_F(FigmentViewImages, RepeatedViewsGiveNumberedImagesOfOneDrape) {
  const std::string scene = write("cloth.iv", fallingSquare(0.01));
  const ProcessResult r =
      run(quote(scene) + " -o " + quote(path("out.png")) +
          " --size 80x60 --view front --view -30,20 --view back --stats " + quote(path("stats.json")));
  ASSERT_EQ(r.status, 0) << r.err;
  // Stopped mid-fall by maxTime: its verdict's one line (test_FigmentViewVerdict.cpp).
  EXPECT_EQ(r.err.rfind("figment-view: " + scene + ": ClothEngine 'Drape': not at rest after maxTime 0.01 s (", 0), 0u)
      << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(images(), (std::set<std::string>{"out-0.png", "out-1.png", "out-2.png"}));
  expectAllDiffer({"out-0.png", "out-1.png", "out-2.png"});
  const nlohmann::json stats = nlohmann::json::parse(std::ifstream(path("stats.json")));
  ASSERT_EQ(stats["garments"].size(), 1u);
  EXPECT_EQ(stats["garments"][0]["iterations"], 10);  // one drape, however many views
}

TEST_F(FigmentViewImages, ATurntableGoesAroundTheScene) {
  const std::string scene = write("cloth.iv", fallingSquare(0.01));
  const ProcessResult r = run(quote(scene) + " -o " + quote(path("turn-%02d.png")) + " --size 80x60 --turntable 4");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(images(), (std::set<std::string>{"turn-00.png", "turn-01.png", "turn-02.png", "turn-03.png"}));
  expectAllDiffer({"turn-00.png", "turn-01.png", "turn-02.png", "turn-03.png"});
  // The same turntable started from a view: the same views, numbered from there.
  const ProcessResult from = run(quote(scene) + " -o " + quote(path("from.png")) +
                                 " --size 80x60 --turntable 4 "
                                 "--view 90,0");
  ASSERT_EQ(from.status, 0) << from.err;
  EXPECT_EQ(pixels(path("from-0.png")), pixels(path("turn-01.png")));  // 90 degrees both
  EXPECT_EQ(pixels(path("from-2.png")), pixels(path("turn-03.png")));  // 270 degrees both
}

namespace {
// Rows of `image` holding something other than the grey background: the figure's
// height in pixels (its top row to its bottom row).
int figureHeight(const figment::test::Image& image) {
  int top = -1, bottom = -1;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (!image.is(y * image.width + x, {204, 204, 204}, 20)) {
        if (top < 0) top = y;
        bottom = y;
        break;
      }
  return top < 0 ? 0 : bottom - top + 1;
}
}  // namespace

TEST_F(FigmentViewImages, ATurntableKeepsOneCameraDistance) {
  // A post 1.8 m high with a bar 1.6 m wide across it (a figure with its arms out): its
  // box needs the camera farther away from the front (the bar across the picture) than
  // from the side (the bar end on). A turntable keeps the farthest distance for every
  // view, so the post keeps its height in pixels; views framed one by one pulse.
  const std::string scene = write("post.iv",
                                  "#Inventor V2.1 ascii\nSeparator {\n"
                                  "  Material { diffuseColor 0.8 0.2 0.2 }\n"
                                  "  Cylinder { radius 0.05 height 1.8 }\n"
                                  "  Translation { translation 0 0.5 0 }\n"
                                  "  Cube { width 1.6 height 0.08 depth 0.1 }\n"
                                  "}\n");
  ASSERT_EQ(run(quote(scene) + " -o " + quote(path("turn.png")) + " --size 240x200 --turntable 8").status, 0);
  std::string views;
  for (int i = 0; i < 8; ++i) views += " --view " + std::to_string(45 * i) + ",0";
  ASSERT_EQ(run(quote(scene) + " -o " + quote(path("each.png")) + " --size 240x200" + views).status, 0);
  int lowest = 1 << 20, highest = 0, eachLowest = 1 << 20, eachHighest = 0;
  for (int i = 0; i < 8; ++i) {
    const int height = figureHeight(figment::test::readPng(path("turn-" + std::to_string(i) + ".png")));
    const int each = figureHeight(figment::test::readPng(path("each-" + std::to_string(i) + ".png")));
    lowest = std::min(lowest, height), highest = std::max(highest, height);
    eachLowest = std::min(eachLowest, each), eachHighest = std::max(eachHighest, each);
  }
  ASSERT_GT(lowest, 50) << "the post is in every picture";
  EXPECT_LE(highest - lowest, 0.02 * highest) << lowest << " to " << highest << " pixels high";
  EXPECT_GT(eachHighest - eachLowest, 0.2 * eachHighest)
      << "the control: views framed one by one pulse (" << eachLowest << " to " << eachHighest << ")";
}

TEST_F(FigmentViewImages, AnErrorAfterSomeImagesLeavesNone) {
  const std::string scene = write("cloth.iv", fallingSquare(0.01));
  // The statistics come after the images, into a folder that cannot be made (a file
  // stands where it would be).
  write("a-file", "x");
  const ProcessResult r = run(quote(scene) + " -o " + quote(path("out.png")) + " --size 80x60 --turntable 3 --stats " +
                              quote(path("a-file/stats.json")));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("a-file/stats.json: cannot make the folder"), std::string::npos) << r.err;
  EXPECT_EQ(images(), std::set<std::string>{});
}

TEST_F(FigmentViewImages, MakesTheFoldersItsOutputsNameAndSaysWhyItCannot) {
  const std::string scene = write("cloth.iv", fallingSquare(0.01));
  const ProcessResult made = run(quote(scene) + " -o " + quote(path("new/deeper/out.png")) + " --size 80x60 --stats " +
                                 quote(path("stats/run.json")));
  ASSERT_EQ(made.status, 0) << made.err;
  EXPECT_EQ(figment::test::readPng(path("new/deeper/out.png")).width, 80);
  EXPECT_TRUE(fs::is_regular_file(path("stats/run.json")));
  write("a-file", "x");
  const ProcessResult refused = run(quote(scene) + " -o " + quote(path("a-file/out.png")) + " --size 80x60");
  EXPECT_EQ(refused.status, 1);
  EXPECT_NE(refused.err.find("a-file/out.png: cannot make the folder"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("Not a directory"), std::string::npos) << refused.err;
}

TEST_F(FigmentViewImages, BadImageOptionsAreOneLineNamingTheOptionAndValue) {
  const std::string scene = write("cloth.iv", fallingSquare(0.01));
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--turntable 0", "--turntable: '0'"},
      {"--turntable many", "--turntable: 'many'"},
      {"--turntable 2 --view front --view back", "--turntable: takes at most one --view"},
      {"--frames 2:1:5", "--frames: '2:1:5'"},
      {"--frames 0:1:0", "--frames: '0:1:0'"},
      {"--frames -1:1:3", "--frames: '-1:1:3'"},
      {"--frames 0:1:3 --turntable 2", "--frames: takes one view, not 2"},
      {"--view front --view up", "--view: 'up'"},
      {"--supersample 0", "usage: --supersample: Value 0 not in range 1 to 8"},
      {"--supersample 9", "usage: --supersample: Value 9 not in range 1 to 8"},
  };
  for (const auto& [options, message] : cases) {
    const ProcessResult r = run(quote(scene) + " -o " + quote(path("out.png")) + " " + options);
    EXPECT_EQ(r.status, 2) << options;
    EXPECT_EQ(r.err.rfind("figment-view: " + message, 0), 0u) << options << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  const ProcessResult twoNumbers = run(quote(scene) + " -o " + quote(path("a%d-%d.png")) + " --turntable 2");
  EXPECT_EQ(twoNumbers.status, 2);
  EXPECT_NE(twoNumbers.err.find("--output: '" + path("a%d-%d.png") + "'"), std::string::npos) << twoNumbers.err;
  EXPECT_EQ(images(), std::set<std::string>{});
}

TEST_F(FigmentViewImages, FramesOfATimeSpanShowTheClothMoving) {
  // The drape's own maxTime (0.01 s) is raised to the last frame's time.
  const std::string scene = write("cloth.iv", fallingSquare(0.01));
  const ProcessResult r = run(quote(scene) + " -o " + quote(path("frame.png")) +
                              " --size 80x60 --view 0,40 --frames 0:0.3:4 --stats " + quote(path("stats.json")));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(images(), (std::set<std::string>{"frame-0.png", "frame-1.png", "frame-2.png", "frame-3.png"}));
  expectAllDiffer({"frame-0.png", "frame-1.png", "frame-2.png", "frame-3.png"});
  const nlohmann::json garment = nlohmann::json::parse(std::ifstream(path("stats.json")))["garments"][0];
  EXPECT_EQ(garment["iterations"], 300);
}

TEST_F(FigmentViewImages, TheWindForceHasThePapersForm) {
  // Paper §2, Fig. 2.2: a sinusoid of the given amplitude and frequency whose phase
  // changes at random moments, pushing each section along the wind by p A |n . w|. The
  // square falls flat, face-on to a vertical wind: it catches p(t) * 1 m^2 along +y.
  const double amplitude = 0.5, frequency = 2.0;
  const std::string scene = write(
      "wind.iv", fallingSquare(3.0, "windDirection 0 2 0 windAmplitude 0.5 windFrequency 2 windPhaseInterval 0.3"));
  const ProcessResult r =
      run(quote(scene) + " -o " + quote(path("out.png")) + " --size 40x30 --wind-force " + quote(path("wind.csv")));
  ASSERT_EQ(r.status, 0) << r.err;
  std::string header;
  const std::vector<WindRow> rows = readWindCsv(path("wind.csv"), header);
  EXPECT_EQ(header, "engine,time_s,pressure_Pa,phase_rad,force_x_N,force_y_N,force_z_N,force_N");
  ASSERT_GE(rows.size(), 600u);  // every 5 ms of 3 s
  double smallest = 1e9, largest = -1e9;
  std::set<double> phases;
  int changes = 0;
  for (size_t i = 0; i < rows.size(); ++i) {
    const WindRow& row = rows[i];
    // p(t) = a sin(2 pi f t + phi(t)) ...
    EXPECT_NEAR(row.pressure, amplitude * std::sin(2.0 * M_PI * frequency * row.time + row.phase), 1e-6) << row.time;
    // ... along the wind, on the section's area facing it.
    EXPECT_NEAR(row.fy, row.pressure, 1e-6) << row.time;
    EXPECT_NEAR(row.fx, 0.0, 1e-9);
    EXPECT_NEAR(row.fz, 0.0, 1e-9);
    EXPECT_NEAR(row.magnitude, std::abs(row.pressure), 1e-6);
    smallest = std::min(smallest, row.pressure);
    largest = std::max(largest, row.pressure);
    phases.insert(row.phase);
    if (i > 0 && row.phase != rows[i - 1].phase) ++changes;
  }
  // Not constant: it swings through nearly the whole amplitude both ways...
  EXPECT_GT(largest, 0.9 * amplitude);
  EXPECT_LT(smallest, -0.9 * amplitude);
  // ... and its phase is piecewise constant, changing now and then (about 10 times in
  // 3 s at a mean interval of 0.3 s), never at every sample.
  EXPECT_GE(changes, 3);
  EXPECT_LE(changes, 40);
  EXPECT_EQ(phases.size(), size_t(changes) + 1);
}

TEST_F(FigmentViewImages, ListNodesNamesFigmentsTypesAndTheirFields) {
  const ProcessResult r = run("--list-nodes");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  for (const char* expected :
       {"ClothEngine (engine, derived from Engine)\n", "Mannequin (node, derived from Group)\n",
        "ClothingLayer (node, derived from IndexedFaceSet)\n", "MeshFile (node", "StencilSeparator (node",
        "  windSeed             SFInt32      1\n", "  fileName             SFString     \"\"\n"})
    EXPECT_NE(r.out.find(expected), std::string::npos) << expected;
  for (const char* coins : {"\nCube (node", "\nSeparator (node", "\nCalculator (engine"})
    EXPECT_EQ(r.out.find(coins), std::string::npos) << coins << " is Coin's";
}

TEST_F(FigmentViewImages, TheWindSceneMovesFromFrameToFrame) {
  // scenes/wind.iv, stopped after 40 steps of 5 ms: the skirt settles on the hips as
  // the wind begins.
  const std::string scene = FIGMENT_SOURCE_DIR "/scenes/wind.iv";
  if (figment::findModelFile("human.zae").empty()) GTEST_SKIP() << "assimp-testmodels' human.zae is not installed";
  const ProcessResult r = run(quote(scene) + " -o " + quote(path("wind.png")) +
                              " --size 60x70 --frames 0.1:0.2:3 --stop-at 40 --wind-force " + quote(path("wind.csv")));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(images(), (std::set<std::string>{"wind-0.png", "wind-1.png", "wind-2.png"}));
  expectAllDiffer({"wind-0.png", "wind-1.png", "wind-2.png"});
  std::string header;
  const std::vector<WindRow> rows = readWindCsv(path("wind.csv"), header);
  ASSERT_GE(rows.size(), 40u);
  // The wind blows along +x: the force on the skirt follows the pressure's sign.
  double largest = 0.0;
  for (const WindRow& row : rows) {
    EXPECT_GE(row.fx * row.pressure, 0.0) << row.time;
    EXPECT_NEAR(row.fy, 0.0, 1e-9);
    largest = std::max(largest, row.magnitude);
  }
  EXPECT_GT(largest, 0.1);  // N: 5 Pa on a few tenths of a square metre facing the wind
}

}  // namespace test_FigmentViewImages
