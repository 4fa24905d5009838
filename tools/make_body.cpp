// figment-body: MakeHuman's body (CC0, docs/bodies.md) made to typed measurements.
//   figment-body --sex female|male [--stature M] [--bust-girth M] [--waist-girth M]
//                [--hip-girth M] [...] -o body.obj|body.glb|body.iv
// Each typed measurement (metres) is met within 5 mm as figment-measure measures it; the
// others follow MakeHuman's macro model. Prints the achieved measurements as one JSON
// object on stdout. A set it cannot reach is one line on stderr naming the measurement
// and the nearest reachable value, exit status 1, and no file.

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "ToolMain.h"
#include "io/MakeHumanFiles.h"
#include "io/MakeHumanLibrary.h"
#include "io/MeshExport.h"
#include "io/MeshSetExport.h"

namespace {

const figment::tools::ToolMain kTool{"figment-body"};

std::string optionName(std::string key) {  // "bust_girth" -> "--bust-girth"
  for (char& c : key)
    if (c == '_') c = '-';
  return "--" + key;
}

// The file name's extension, lower case: ".obj".
std::string extensionOf(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

bool writable(const std::string& path) {
  const std::string extension = extensionOf(path);
  return extension == ".obj" || extension == ".glb" || extension == ".gltf" || extension == ".iv";
}

// The body in the format its name asks for: a Wavefront OBJ, glTF (binary .glb or .gltf
// with its .bin; smooth normals, a skin colour) or Coin's .iv text; whole or not at all.
void writeBody(const figment::TriangleMesh& body, const std::string& path) {
  const std::string extension = extensionOf(path);
  if (extension == ".obj") return figment::exportObj(body, path);
  if (extension == ".iv") return figment::exportIv(body, path);
  figment::ColouredMesh skin{
      .name = "body", .mesh = body, .normals = figment::vertexNormals(body), .colour = {0.80f, 0.58f, 0.45f}};
  figment::exportMeshSet({skin}, path);
}

void printJson(const figment::MeasuredBody& made) {
  std::printf("{");
  const auto named = made.achieved.named();
  for (size_t i = 0; i < named.size(); ++i)
    std::printf("%s\"%s\": %.5f", i ? ", " : "", named[i].first.c_str(), named[i].second);
  std::printf(
      ", \"parameters\": {\"gender\": %g, \"age\": %g, \"muscle\": %g, \"weight\": %g, \"height\": %.4f, "
      "\"cupSize\": %g",
      made.parameters.macro.gender, made.parameters.macro.age, made.parameters.macro.muscle,
      made.parameters.macro.weight, made.parameters.macro.height, made.parameters.macro.cupSize);
  for (const auto& [key, value] : made.parameters.measures) std::printf(", \"%s\": %.4f", key.c_str(), value);
  std::printf("}}\n");
}

int make(const figment::HumanParameters& start, const std::vector<figment::MeasurementGoal>& goals,
         const std::string& output) {
  figment::MakeHumanLibrary human;
  if (human.dir().empty()) return kTool.fail(figment::kMakeHumanDataMissing);
  try {
    const figment::MeasuredBody made = human.measuredBody(start, goals);
    writeBody(figment::numberedByFirstUse(made.body), output);
    printJson(made);
    return 0;
  } catch (const std::exception& error) {
    return kTool.fail(error.what());
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Makes MakeHuman's body to typed measurements (metres) and writes it as a Wavefront OBJ, glTF or "
      "Open Inventor (.iv) file.",
      kTool.program()};
  std::string sex, output;
  figment::HumanParameters start;
  std::map<std::string, double> typed;
  app.add_option("--sex", sex, "female or male")->required()->check(CLI::IsMember({"female", "male"}));
  for (const auto& [key, parameter] : figment::measurableKeys())
    app.add_option_function<double>(
        optionName(key), [&typed, k = key](double v) { typed[k] = v; },
        key + ", m (moves MakeHuman's " + parameter + ")");
  app.add_option("--age", start.macro.age, "MakeHuman's age, 0.5 = 25 years, 1 = 90")->check(CLI::Range(0.0, 1.0));
  app.add_option("--muscle", start.macro.muscle, "MakeHuman's muscle, 0 to 1")->check(CLI::Range(0.0, 1.0));
  app.add_option("--weight", start.macro.weight, "MakeHuman's weight, 0 to 1")->check(CLI::Range(0.0, 1.0));
  app.add_option("-o,--output", output, "file to write: .obj, .glb, .gltf or .iv")->required();
  if (const int status = kTool.parse(app, argc, argv); status >= 0) return status;
  if (!writable(output)) return kTool.fail(output + ": only .obj, .glb, .gltf and .iv are written");
  start.macro.gender = sex == "male" ? 1.0 : 0.0;
  std::vector<figment::MeasurementGoal> goals;
  for (const auto& [key, value] : typed) goals.push_back({key, value});
  return make(start, goals, output);
}
