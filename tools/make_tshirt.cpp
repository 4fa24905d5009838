// figment-make-tshirt: generates a T-shirt with short sleeves (scenes/tshirt.obj) around
// a body in its rest pose, of any number of triangles.
//   figment-make-tshirt [--body human.zae] [--triangles 1000] -o scenes/tshirt.obj
//   (and [--metres-per-unit M] [--up-axis AXIS] for a body in another unit or frame)
// The body is found through the model search path and read as a MeshFile with the same
// fields reads it (metres, y up, without its eyes); a body that then does not stand along
// +y at a human stature is refused (tools/ToolMain.h). On success one summary line goes
// to stdout. Any error is one line,
// "figment-make-tshirt: <file>: <reason>", on stderr and exit status 1, with no output file.

#include <cstdio>
#include <string>
#include <vector>

#include "ToolMain.h"
#include "io/MeshExport.h"
#include "sim/garment/TShirt.h"

namespace {

const figment::tools::ToolMain kTool{"figment-make-tshirt"};

int makeAndWrite(const figment::TriangleMesh& body, const figment::TShirtOptions& options, const std::string& output) {
  const figment::TShirt shirt = figment::makeTShirt(body, options);
  figment::exportObj(shirt.mesh, output);
  std::printf("%s: %s: %zu vertices, %zu triangles (from %d of the skin), %.3f m^2; hem at %.3f m\n",
              kTool.program().c_str(), output.c_str(), shirt.mesh.vertices.size(), shirt.mesh.triangles.size(),
              shirt.skinTriangles, shirt.area, shirt.hemHeight);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Generates a T-shirt with short sleeves around a body and writes it as a Wavefront OBJ.",
               kTool.program()};
  figment::tools::BodyInput body;
  std::string output;
  figment::TShirtOptions options;
  figment::tools::addBodyOptions(app, body);
  app.add_option("-o,--output", output, "OBJ file to write")->required();
  app.add_option("--triangles", options.triangles, "sections of the shirt")->capture_default_str();
  app.add_option("--ease", options.ease, "how far the shirt stands off the skin, m")->capture_default_str();
  app.add_option("--hem-above-crotch", options.hemAboveCrotch, "the hem's height above the crotch, m")
      ->capture_default_str();
  app.add_option("--sleeve-share", options.sleeveShare, "share of the upper arm inside the sleeve")
      ->capture_default_str();
  if (const int status = kTool.parse(app, argc, argv); status >= 0) return status;
  return kTool.withBody(body, [&](const figment::TriangleMesh& bodyMesh, const std::string&) {
    return makeAndWrite(bodyMesh, options, output);
  });
}
