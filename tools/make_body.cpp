// figment-body: MakeHuman's body (CC0, docs/bodies.md) made to typed measurements.
//   figment-body --sex female|male [--stature M] [--bust-girth M] [--waist-girth M]
//                [--hip-girth M] [...] -o body.obj
// Each typed measurement (metres) is met within 5 mm as figment-measure measures it; the
// others follow MakeHuman's macro model. Prints the achieved measurements as one JSON
// object on stdout. A set it cannot reach is one line on stderr naming the measurement
// and the nearest reachable value, exit status 1, and no file.

#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "ToolMain.h"
#include "io/MakeHumanFiles.h"
#include "io/MeshExport.h"
#include "io/TargetLibrary.h"
#include "sim/body/BodyFit.h"

namespace {

const figment::tools::ToolMain kTool{"figment-body"};

std::string optionName(std::string key) {  // "bust_girth" -> "--bust-girth"
  for (char& c : key)
    if (c == '_') c = '-';
  return "--" + key;
}

void printJson(const figment::BodyFitResult& fit) {
  std::printf("{");
  const auto named = fit.achieved.named();
  for (size_t i = 0; i < named.size(); ++i)
    std::printf("%s\"%s\": %.5f", i ? ", " : "", named[i].first.c_str(), named[i].second);
  std::printf(
      ", \"parameters\": {\"gender\": %g, \"age\": %g, \"muscle\": %g, \"weight\": %g, \"height\": %.4f, "
      "\"cupSize\": %g",
      fit.parameters.macro.gender, fit.parameters.macro.age, fit.parameters.macro.muscle, fit.parameters.macro.weight,
      fit.parameters.macro.height, fit.parameters.macro.cupSize);
  for (const auto& [key, value] : fit.parameters.measures) std::printf(", \"%s\": %.4f", key.c_str(), value);
  std::printf("}}\n");
}

int make(const figment::HumanParameters& start, const std::vector<figment::MeasurementGoal>& goals,
         const std::string& output) {
  const std::string dir = figment::findMakeHumanData();
  if (dir.empty()) return kTool.fail("MakeHuman's data not found: run scripts/setup.sh, or set FIGMENT_MAKEHUMAN_DIR");
  try {
    figment::TargetLibrary library(dir);
    const figment::HumanModel model = figment::loadHumanModel(dir, library);
    const figment::BodyFitResult fit = figment::fitBody(model, start, goals);
    figment::exportObj(figment::numberedByFirstUse(fit.body), output);
    printJson(fit);
    return 0;
  } catch (const std::exception& error) {
    return kTool.fail(error.what());
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Makes MakeHuman's body to typed measurements (metres) and writes it as a Wavefront OBJ.",
               kTool.program()};
  std::string sex, output;
  figment::HumanParameters start;
  std::map<std::string, double> typed;
  app.add_option("--sex", sex, "female or male")->required()->check(CLI::IsMember({"female", "male"}));
  for (const auto& [key, parameter] : figment::fittedKeys())
    app.add_option_function<double>(
        optionName(key), [&typed, k = key](double v) { typed[k] = v; },
        key + ", m (moves MakeHuman's " + parameter + ")");
  app.add_option("--age", start.macro.age, "MakeHuman's age, 0.5 = 25 years, 1 = 90")->check(CLI::Range(0.0, 1.0));
  app.add_option("--muscle", start.macro.muscle, "MakeHuman's muscle, 0 to 1")->check(CLI::Range(0.0, 1.0));
  app.add_option("--weight", start.macro.weight, "MakeHuman's weight, 0 to 1")->check(CLI::Range(0.0, 1.0));
  app.add_option("-o,--output", output, "OBJ file to write")->required();
  if (const int status = kTool.parse(app, argc, argv); status >= 0) return status;
  if (!output.ends_with(".obj")) return kTool.fail(output + ": only .obj is written");
  start.macro.gender = sex == "male" ? 1.0 : 0.0;
  std::vector<figment::MeasurementGoal> goals;
  for (const auto& [key, value] : typed) goals.push_back({key, value});
  return make(start, goals, output);
}
