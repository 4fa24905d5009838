// figment-bench reads its scenes through the same session, so the same guard, as figment-view:
// the bad input of issue 28 is one line and a non-zero exit, and the render study, which
// rendered without the draw-side check before, refuses a shape indexing past its data. The
// drape study says whether each drape is clean.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/ProgramRun.h"
#include "support/TempDir.h"

namespace {

using figment::test::quote;
using ProcessResult = figment::test::ProgramResult;

class FigmentBench : public ::testing::Test {
 protected:
  std::string write(const std::string& name, const std::string& text) const { return dir_.file(name, text); }
  // Runs figment-bench with `arguments` (shell words), capturing stderr.
  ProcessResult run(const std::string& arguments) const {
    return figment::test::runProgram(FIGMENT_BENCH_EXECUTABLE, arguments, dir_.path(), dir_.path() / "cache");
  }
  std::string out() const { return quote((dir_.path() / "out").string()); }

  figment::test::TempDir dir_;
};

// The scene of issue 28: an included volumes file whose CapsuleVolume declares a field the node
// does not have (SIGSEGV before).
std::string writeCrashScene(const figment::test::TempDir& dir) {
  dir.file("volumes.iv",
           "#Inventor V2.1 ascii\nGroup {\n  CapsuleVolume {\n    fields [ SFString part, SFFloat r1e308 ]\n"
           "    part \"head\"\n  }\n  CapsuleVolume { fields [ SFString part ] part \"neck\" }\n}\n");
  return dir.file("scene.iv", "#Inventor V2.1 ascii\nSeparator {\n  File { name \"volumes.iv\" }\n  Cube { }\n}\n");
}

// A square of cloth draped by a ClothEngine with `fields` (its time step and run).
std::string squareOfCloth(const std::string& fields) {
  return "#Inventor V2.1 ascii\nSeparator {\n"
         "  Coordinate3 { point = DEF Drape ClothEngine {\n"
         "    restPoints [ -0.5 1 -0.5, 0.5 1 -0.5, 0.5 1 0.5, -0.5 1 0.5 ]\n"
         "    coordIndex [ 0 3 2 1 -1 ]  " +
         fields + "\n  } . positions }\n  IndexedFaceSet { coordIndex [ 0 3 2 1 -1 ] }\n}\n";
}

void expectOneLine(const ProcessResult& r, const std::string& words) {
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
  EXPECT_EQ(r.err.rfind("figment-bench: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(words), std::string::npos) << words << " in: " << r.err;
}

}  // namespace

TEST_F(FigmentBench, RefusesAFieldDeclarationTheNodeDoesNotHaveInOneLine) {
  const std::string scene = writeCrashScene(dir_);
  const std::string words =
      "scene.iv: line 4: CapsuleVolume: fields [ SFFloat r1e308 ] declares a field "
      "CapsuleVolume does not have (in ";
  expectOneLine(run("render --scene " + quote(scene) + " --repeat 1 --out " + out()), words);
  expectOneLine(run("drape --scene " + quote(scene) + " --repeat 1 --out " + out()), words);
  EXPECT_FALSE(std::filesystem::exists(dir_.path() / "out" / "render.csv"));
}

// --out naming a file: one line and exit 1 before the study runs (an uncaught
// std::filesystem error and an abort before, after the study's work).
TEST_F(FigmentBench, AnOutFolderThatIsAFileIsRefusedBeforeTheStudy) {
  const std::string file = write("taken", "a file\n");
  const std::string scene = write("square.iv", squareOfCloth("timeStep 0.01 maxTime 0.05"));
  for (const char* study : {"drape", "tradeoff --quick"}) {
    const ProcessResult r = run(std::string(study) + " --scene " + quote(scene) + " --out " + quote(file));
    expectOneLine(r, "--out " + file + ": not a folder");
  }
}

TEST_F(FigmentBench, TheRenderStudyRefusesAShapeIndexingPastItsData) {
  const std::string scene = write("faces.iv",
                                  "#Inventor V2.1 ascii\nSeparator {\n  Coordinate3 { point [ 0 0 0, 1 0 0, 0 1 0 ] }\n"
                                  "  IndexedFaceSet { coordIndex [ 0 1 2147483647 -1 ] }\n}\n");
  expectOneLine(run("render --scene " + quote(scene) + " --repeat 1 --out " + out()),
                "faces.iv: IndexedFaceSet: coordIndex[2] = 2147483647 is not a vertex: the coordinates have 3 points");
}

// The drape study says each drape's verdict: in its CSV (clean, the most stretched edge,
// the step control's halved and failed steps) and on its line.
TEST_F(FigmentBench, TheDrapeStudySaysWhetherEachDrapeIsClean) {
  const std::string scene = write("cloth.iv", squareOfCloth("timeStep 0.001  maxTime 0.01"));
  const std::string stdoutFile = (dir_.path() / "stdout.txt").string();
  const int raw = std::system((quote(FIGMENT_BENCH_EXECUTABLE) + " drape --scene " + quote(scene) +
                               " --repeat 1 --out " + out() + " > " + quote(stdoutFile) + " 2> /dev/null")
                                  .c_str());
  ASSERT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == 0);
  std::stringstream said;
  said << std::ifstream(stdoutFile).rdbuf();
  EXPECT_NE(said.str().find("; not clean: not at rest after maxTime 0.01 s"), std::string::npos) << said.str();
  std::ifstream csv(dir_.path() / "out" / "drape.csv");
  std::string header, row;
  std::getline(csv, header);
  std::getline(csv, row);
  EXPECT_NE(header.find(",clean,max_edge_stretch,halved_steps,failed_steps"), std::string::npos) << header;
  EXPECT_NE(row.find(",0,1,0,0"), std::string::npos) << row;  // not clean, unstretched, no step control
}

// The progressive study counts a script's levels with a drape of one coarse step. On a scene
// at the paper's explicit step (the skirt: HEUN, 1.5e-4 s) a coarse level may step up to
// twice as long, which the probe's maxTime of one scene step refused ("timeStep = 3e-04
// must not exceed maxTime = 0.00015") before it counted anything.
TEST_F(FigmentBench, TheProgressiveStudyCountsTheLevelsOfAnExplicitScene) {
  const std::string scene = (std::filesystem::path(FIGMENT_SOURCE_DIR) / "scenes" / "skirt.iv").string();
  const ProcessResult r = run("progressive --scene " + quote(scene) +
                              " --method implicit:0.05 --schedule 0:300 --step-factor 1 --out " + out());
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream csv(dir_.path() / "out" / "progressive.csv");
  std::string header, row;
  std::getline(csv, header);
  std::getline(csv, row);
  ASSERT_EQ(header.rfind("scene,method,time_steps,begin_level,levels,", 0), 0u) << header;
  std::stringstream fields(row);
  std::string field;
  for (int column = 0; column < 5; ++column) std::getline(fields, field, ',');
  EXPECT_GT(std::stoi(field), 1) << row;  // the skirt's script has levels to split through
}

// A ClothEngine's error is the study's one line: Coin's own "Coin error in
// ClothEngine::evaluate()" line, printed by its default handler, came before it.
TEST_F(FigmentBench, AnEnginesErrorIsOneLine) {
  const std::string scene = write("cloth.iv", squareOfCloth("timeStep 0.1  maxTime 0.01"));
  expectOneLine(run("drape --scene " + quote(scene) + " --repeat 1 --out " + out()),
                "timeStep = 0.1 must not exceed maxTime = 0.01");
}
