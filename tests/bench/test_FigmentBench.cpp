// figment-bench reads its scenes through the same session, so the same guard, as figment-view:
// the bad input of issue 28 is one line and a non-zero exit, and the render study, which
// rendered without the draw-side check before, refuses a shape indexing past its data.

#include "support/TempDir.h"

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

std::string quote(const std::string& text) {
  return std::string("'").append(text).append("'");
}

struct ProcessResult {
  int status = -1;
  std::string err;
};

class FigmentBench : public ::testing::Test {
 protected:
  std::string write(const std::string& name, const std::string& text) const { return dir_.file(name, text); }
  // Runs figment-bench with `arguments` (shell words), capturing stderr.
  ProcessResult run(const std::string& arguments) const {
    const std::string err = (dir_.path() / "stderr.txt").string();
    const std::string command = "XDG_CACHE_HOME=" + quote((dir_.path() / "cache").string()) + " " +
                                quote(FIGMENT_BENCH_EXECUTABLE) + " " + arguments + " 2> " + quote(err) +
                                " > /dev/null";
    const int raw = std::system(command.c_str());
    std::stringstream text;
    text << std::ifstream(err).rdbuf();
    return ProcessResult{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, text.str()};
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

TEST_F(FigmentBench, TheRenderStudyRefusesAShapeIndexingPastItsData) {
  const std::string scene = write("faces.iv",
                                  "#Inventor V2.1 ascii\nSeparator {\n  Coordinate3 { point [ 0 0 0, 1 0 0, 0 1 0 ] }\n"
                                  "  IndexedFaceSet { coordIndex [ 0 1 2147483647 -1 ] }\n}\n");
  expectOneLine(run("render --scene " + quote(scene) + " --repeat 1 --out " + out()),
                "faces.iv: IndexedFaceSet: coordIndex[2] = 2147483647 is not a vertex: the coordinates have 3 points");
}
