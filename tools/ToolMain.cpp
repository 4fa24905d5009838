#include "ToolMain.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <stdexcept>

#include "io/MeshImport.h"
#include "sim/body/BodyStance.h"
#include "sim/core/ParameterChecks.h"

namespace figment::tools {

namespace {

// A stature in the middle of kMinStature..kMaxStature, for the suggested --metres-per-unit.
constexpr double kTypicalStature = 1.7;  // m

// Three significant digits: enough to see what is wrong, short enough to type.
std::string suggestion(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

}  // namespace

void addBodyOptions(CLI::App& app, BodyInput& body) {
  app.add_option("--body", body.name, "body model file, looked up on the model search path")->capture_default_str();
  app.add_option("--exclude", body.exclude, "meshes of the body file to leave out (name or part of it)")
      ->capture_default_str();
  app.add_option("--metres-per-unit", body.metresPerUnit,
                 "the body file's unit in metres, as MeshFile.metresPerUnit (0.01 for centimetres); the body must "
                 "come out 0.8 to 2.5 m tall")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            char* end = nullptr;
            const double value = std::strtod(text.c_str(), &end);
            if (end != text.c_str() && *end == '\0' && std::isfinite(value) && value > 0.0) return "";
            return text + " must be a number > 0";
          },
          "M"))
      ->capture_default_str();
  app.add_option_function<std::string>(
         "--up-axis",
         [&body](const std::string& name) {
           const std::optional<UpAxis> axis = parseUpAxis(name);
           if (!axis) throw CLI::ValidationError("--up-axis", name + " is not X, Y, Z, NEG_X, NEG_Y or NEG_Z");
           body.upAxis = *axis;
         },
         "the body file's up axis, as MeshFile.upAxis: X, Y, Z, NEG_X, NEG_Y or NEG_Z (default Y); the body must "
         "stand with its feet apart below and its head above")
      ->type_name("AXIS");
}

std::string bodyFrameProblem(const TriangleMesh& body, const BodyInput& input) {
  const BodyStance stance = measureStance(body);
  if (!stance.up)
    return "no axis has two feet at its low end and one head at its high end: not a standing human body "
           "(legs apart, arms away from the sides)";
  const std::string tall =
      suggestion(stance.stature) + " m tall at --metres-per-unit " + formatNumber(input.metresPerUnit);
  const bool upright = stance.up->y() > 0.5;
  const bool humanSize = stance.stature >= kMinStature && stance.stature <= kMaxStature;
  if (upright && humanSize) return "";
  std::string problem = "the body ";
  std::string fix;
  if (!upright) {
    const std::optional<UpAxis> fileAxis = fileUpAxis(*stance.up, input.upAxis);
    problem += "stands along its file's " + upAxisName(fileAxis.value_or(UpAxis::Y)) + " axis, not y";
    fix += "--up-axis " + upAxisName(fileAxis.value_or(UpAxis::Y));
  }
  if (!humanSize) {
    problem += std::string(upright ? "" : ", and ") + "is " + tall + ", not " + formatNumber(kMinStature) + " to " +
               formatNumber(kMaxStature) + " m";
    fix += std::string(fix.empty() ? "" : " ") + "--metres-per-unit " +
           suggestion(input.metresPerUnit * kTypicalStature / stance.stature) + " (for " +
           formatNumber(kTypicalStature) + " m)";
  }
  return problem + ": try " + fix;
}

int ToolMain::fail(const std::string& message) const {
  std::fprintf(stderr, "%s: %s\n", program_.c_str(), message.c_str());
  return 1;
}

int ToolMain::parse(CLI::App& app, int argc, char** argv) const {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& help) {
    return app.exit(help);
  } catch (const CLI::ParseError& error) {
    return fail(error.what());
  }
  return -1;
}

int ToolMain::withBody(const BodyInput& input,
                       const std::function<int(const TriangleMesh& body, const std::string& bodyPath)>& work) const {
  const std::string bodyPath = findModelFile(input.name);
  if (bodyPath.empty())
    return fail(input.name +
                ": not found (searched the working directory, $FIGMENT_MODEL_PATH, /usr/share/assimp/models)");
  try {
    ImportOptions options;
    options.exclude = input.exclude;
    options.metresPerUnit = input.metresPerUnit;
    options.upAxis = input.upAxis;
    const TriangleMesh body = importMesh(bodyPath, options).mesh;
    if (const std::string problem = bodyFrameProblem(body, input); !problem.empty())
      return fail(bodyPath + ": " + problem);
    return work(body, bodyPath);
  } catch (const std::runtime_error& error) {  // the importer's and exporter's messages start with the path
    return fail(error.what());
  } catch (const std::exception& error) {
    return fail(bodyPath + ": " + error.what());
  }
}

}  // namespace figment::tools
