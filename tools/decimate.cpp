// figment-decimate: writes a garment's progressive mesh (paper §4) as a reconstruction
// script, the vertex splits that rebuild it from a decimated level.
//   figment-decimate scenes/dress.obj -o scenes/dress.pm [--faces 400]
// The garment is read as a scene's MeshFile reads it (metres, y up, seams welded). On
// success one summary line goes to stdout; any error is one line on stderr, exit 1, and
// no output file.

#include <chrono>
#include <cstdio>
#include <exception>
#include <string>

#include "ToolMain.h"
#include "io/MeshImport.h"
#include "io/ProgressiveScript.h"
#include "sim/progressive/Decimation.h"

namespace {

const figment::tools::ToolMain kTool{"figment-decimate"};

int decimateAndWrite(const std::string& input, const figment::DecimationOptions& options, const std::string& output) {
  const figment::TriangleMesh garment = figment::importMesh(input).mesh;
  const auto start = std::chrono::steady_clock::now();
  const figment::ProgressiveMesh mesh = figment::decimate(garment, options);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  figment::writeProgressiveScript(mesh, output);
  const figment::MeshLevel coarsest(mesh);
  std::printf("%s: %s: %zu sections -> %d at the coarsest level (%d vertices), %d splits, %.2f s\n",
              kTool.program().c_str(), output.c_str(), garment.triangles.size(), coarsest.activeFaces(),
              coarsest.activeVertices(), mesh.levels(), seconds);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Decimates a garment by edge collapses and writes the vertex splits that rebuild it.", kTool.program()};
  std::string input, output;
  figment::DecimationOptions options;
  options.targetFaces = 200;
  app.add_option("garment", input, "garment mesh file (any format assimp reads)")->required();
  app.add_option("-o,--output", output, "reconstruction script to write")->required();
  app.add_option("--faces", options.targetFaces, "sections at the coarsest level (fewer where nothing may collapse)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  app.add_option("--perimeter-weight", options.perimeterWeight, "weight of the perimeter's deviation")
      ->capture_default_str();
  app.add_option("--homogeneity", options.homogeneity, "weight of the sections' even size")->capture_default_str();
  if (const int status = kTool.parse(app, argc, argv); status >= 0) return status;
  try {
    return decimateAndWrite(input, options, output);
  } catch (const std::exception& error) {
    return kTool.fail(error.what());
  }
}
