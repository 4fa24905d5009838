// figment-make-dress: generates the default garment (scenes/dress.obj) around a body.
//   figment-make-dress [--body human.zae] -o scenes/dress.obj
// The body is found through the model search path (findModelFile) and read in metres,
// y up, without its eyes; on success one summary line goes to stdout. Any error is one line,
// "figment-make-dress: <file>: <reason>", on stderr and exit status 1, with no output file.

#include "io/MeshExport.h"
#include "io/MeshImport.h"
#include "sim/garment/StrapDress.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <string>
#include <vector>

namespace {

constexpr const char* kProgram = "figment-make-dress";

int fail(const std::string& message) {
  std::fprintf(stderr, "%s: %s\n", kProgram, message.c_str());
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Generates a strap dress around a body and writes it as a Wavefront OBJ.", kProgram};
  std::string bodyName = "human.zae";
  std::string output;
  std::vector<std::string> exclude = {"eyes"};
  figment::StrapDressOptions options;
  app.add_option("--body", bodyName, "body model file, looked up on the model search path")->capture_default_str();
  app.add_option("-o,--output", output, "OBJ file to write")->required();
  app.add_option("--exclude", exclude, "meshes of the body file to leave out (name or part of it)")
      ->capture_default_str();
  app.add_option("--clearance", options.clearance, "gap between body and dress at the start, m")
      ->capture_default_str();
  app.add_option("--neckline-rise", options.necklineRise, "rise of the top edge between the straps, m")
      ->capture_default_str();
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& help) {
    return app.exit(help);
  } catch (const CLI::ParseError& error) {
    return fail(error.what());
  }

  const std::string bodyPath = figment::findModelFile(bodyName);
  if (bodyPath.empty())
    return fail(bodyName + ": not found (searched the working directory, $FIGMENT_MODEL_PATH, /usr/share/assimp/models)");
  figment::StrapDress dress;
  try {
    figment::ImportOptions importOptions;
    importOptions.exclude = exclude;
    const figment::ImportedMesh body = figment::importMesh(bodyPath, importOptions);
    dress = figment::makeStrapDress(body.mesh, options);
  } catch (const std::runtime_error& error) {  // the importer's message starts with the path
    return fail(error.what());
  } catch (const std::exception& error) {
    return fail(bodyPath + ": " + error.what());
  }
  try {
    figment::exportObj(dress.mesh, output);
  } catch (const std::exception& error) {
    return fail(error.what());
  }
  std::printf("%s: %s: %zu vertices, %zu triangles, top %.3f m (%.3f m between the straps), hem %.3f m, "
              "straps at x = %.3f, %.3f m\n",
              kProgram, output.c_str(), dress.mesh.vertices.size(), dress.mesh.triangles.size(), dress.topHeight,
              dress.necklineHeight, dress.hemHeight,
              dress.strapX[0], dress.strapX[1]);
  return 0;
}
