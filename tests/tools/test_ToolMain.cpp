// What every tool's main does around its work: its command line's exit statuses, the one line
// of an error, and the body's check with the option that would bring it upright and to size.
#include <gtest/gtest.h>

#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "support/BoxFigure.h"
#include "support/TempDir.h"
#include "tools/ToolMain.h"

using namespace figment;
using namespace figment::tools;

namespace {

TriangleMesh scaled(TriangleMesh mesh, const Eigen::Matrix3d& m) {
  for (Vec3& v : mesh.vertices) v = m * v;
  return mesh;
}

// The mesh as an OBJ file, for withBody to find and read.
std::string writeObj(const test::TempDir& dir, const TriangleMesh& mesh) {
  std::string text;
  for (const Vec3& v : mesh.vertices)
    text += "v " + std::to_string(v.x()) + " " + std::to_string(v.y()) + " " + std::to_string(v.z()) + "\n";
  for (const Triangle& t : mesh.triangles)
    text += "f " + std::to_string(t[0] + 1) + " " + std::to_string(t[1] + 1) + " " + std::to_string(t[2] + 1) + "\n";
  return dir.file("figure.obj", text);
}

TEST(ToolMain, FailPrintsOneLineAfterTheProgramsName) {
  testing::internal::CaptureStderr();
  EXPECT_EQ(ToolMain("figment-test").fail("body.obj: not found"), 1);
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "figment-test: body.obj: not found\n");
}

TEST(ToolMain, ParseSaysWhetherToGoOn) {
  const ToolMain tool("figment-test");
  BodyInput body;
  CLI::App app;
  addBodyOptions(app, body);
  std::vector<std::string> good = {"figment-test", "--up-axis", "z", "--metres-per-unit", "0.01"};
  std::vector<char*> argv;
  for (std::string& arg : good) argv.push_back(arg.data());
  EXPECT_EQ(tool.parse(app, int(argv.size()), argv.data()), -1);
  EXPECT_EQ(body.upAxis, UpAxis::Z);
  EXPECT_DOUBLE_EQ(body.metresPerUnit, 0.01);
  CLI::App again;
  addBodyOptions(again, body);
  std::vector<std::string> bad = {"figment-test", "--metres-per-unit", "-1"};
  argv.clear();
  for (std::string& arg : bad) argv.push_back(arg.data());
  testing::internal::CaptureStderr();
  EXPECT_EQ(tool.parse(again, int(argv.size()), argv.data()), 1);
  const std::string printed = testing::internal::GetCapturedStderr();
  EXPECT_EQ(printed.rfind("figment-test: ", 0), 0u) << printed;
  EXPECT_NE(printed.find("-1 must be a number > 0"), std::string::npos) << printed;
}

TEST(ToolMain, AnUprightHumanSizedBodyPasses) {
  EXPECT_EQ(bodyFrameProblem(mannequin::stanceFigure(), BodyInput{}), "");
}

TEST(ToolMain, ABodyInCentimetresIsToldItsUnit) {
  const std::string problem =
      bodyFrameProblem(scaled(mannequin::stanceFigure(), 100 * Eigen::Matrix3d::Identity()), BodyInput{});
  EXPECT_EQ(problem,
            "the body is 175 m tall at --metres-per-unit 1, not 0.8 to 2.5 m: try --metres-per-unit 0.00971 "
            "(for 1.7 m)");
}

TEST(ToolMain, ABodyStandingAlongZIsToldItsAxis) {
  Eigen::Matrix3d yToZ;
  yToZ << 1, 0, 0, 0, 0, -1, 0, 1, 0;  // +y goes to +z
  const std::string problem = bodyFrameProblem(scaled(mannequin::stanceFigure(), yToZ), BodyInput{});
  EXPECT_EQ(problem, "the body stands along its file's Z axis, not y: try --up-axis Z");
}

TEST(ToolMain, WithBodyGivesTheWorkTheBodyAndTurnsItsErrorIntoOneLine) {
  const test::TempDir dir;
  BodyInput input;
  input.name = writeObj(dir, mannequin::stanceFigure());
  input.exclude = {};
  const ToolMain tool("figment-test");
  size_t vertices = 0;
  EXPECT_EQ(tool.withBody(input,
                          [&](const TriangleMesh& body, const std::string&) {
                            vertices = body.vertices.size();
                            return 0;
                          }),
            0);
  EXPECT_GT(vertices, 0u);
  testing::internal::CaptureStderr();
  EXPECT_EQ(tool.withBody(input,
                          [](const TriangleMesh&, const std::string&) -> int {
                            throw std::invalid_argument("clearance = -1 must be >= 0");
                          }),
            1);
  const std::string printed = testing::internal::GetCapturedStderr();
  EXPECT_EQ(printed.find('\n'), printed.size() - 1) << printed;
  EXPECT_NE(printed.find("clearance = -1 must be >= 0"), std::string::npos) << printed;
  input.name = (dir.path() / "nothere.obj").string();
  testing::internal::CaptureStderr();
  EXPECT_EQ(tool.withBody(input, [](const TriangleMesh&, const std::string&) { return 0; }), 1);
  EXPECT_EQ(testing::internal::GetCapturedStderr().rfind("figment-test: ", 0), 0u);
}

}  // namespace
