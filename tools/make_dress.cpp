// figment-make-dress: generates the default garment (scenes/dress.obj) around a body.
//   figment-make-dress [--body human.zae] [--metres-per-unit M] [--up-axis AXIS] -o scenes/dress.obj
// The body is found through the model search path (findModelFile) and read as a MeshFile
// with the same fields reads it (metres, y up, without its eyes); a body that then does
// not stand along +y at a human stature is refused (tools/ToolMain.h) with the options
// that would fix it. On success one summary line goes to stdout. Any error is one line,
// "figment-make-dress: <file>: <reason>", on stderr and exit status 1, with no output file.

#include <CLI/CLI.hpp>
#include <cstdio>
#include <string>
#include <vector>

#include "ToolMain.h"
#include "io/MeshExport.h"
#include "sim/garment/StrapDress.h"

namespace {

const figment::tools::ToolMain kTool{"figment-make-dress"};

// Makes the dress around `body` and writes it: the exit status.
int makeAndWrite(const figment::TriangleMesh& body, const figment::StrapDressOptions& options,
                 const std::string& output) {
  const figment::StrapDress dress = figment::makeStrapDress(body, options);
  figment::exportObj(dress.mesh, output);
  std::printf(
      "%s: %s: %zu vertices, %zu triangles, top %.3f m (%.3f m between the straps), hem %.3f m, "
      "straps at x = %.3f, %.3f m\n",
      kTool.program().c_str(), output.c_str(), dress.mesh.vertices.size(), dress.mesh.triangles.size(), dress.topHeight,
      dress.necklineHeight, dress.hemHeight, dress.strapX[0], dress.strapX[1]);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Generates a strap dress around a body and writes it as a Wavefront OBJ.", kTool.program()};
  figment::tools::BodyInput body;
  std::string output;
  figment::StrapDressOptions options;
  figment::tools::addBodyOptions(app, body);
  app.add_option("-o,--output", output, "OBJ file to write")->required();
  app.add_option("--clearance", options.clearance, "gap between body and dress at the start, m")->capture_default_str();
  app.add_option("--neckline-rise", options.necklineRise, "rise of the top edge between the straps, m")
      ->capture_default_str();
  app.add_option("--strap-offset", options.strapOffset,
                 "|x| of each strap's centre line from the torso's centre, m (nearer the neck for sloping shoulders)")
      ->capture_default_str();
  if (const int status = kTool.parse(app, argc, argv); status >= 0) return status;
  return kTool.withBody(body, [&](const figment::TriangleMesh& bodyMesh, const std::string&) {
    return makeAndWrite(bodyMesh, options, output);
  });
}
