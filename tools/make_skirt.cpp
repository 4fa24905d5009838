// figment-make-skirt: generates the flared skirt (scenes/skirt.obj) around a body.
//   figment-make-skirt [--body human.zae] [--metres-per-unit M] [--up-axis AXIS] -o scenes/skirt.obj
// The body is found through the model search path and read as a MeshFile with the same
// fields reads it (metres, y up, without its eyes); a body that then does not stand along
// +y at a human stature is refused (tools/ToolMain.h). On success one summary line goes
// to stdout. Any error is one line,
// "figment-make-skirt: <file>: <reason>", on stderr and exit status 1, with no output file.

#include <cstdio>
#include <string>
#include <vector>

#include "ToolMain.h"
#include "io/MeshExport.h"
#include "sim/garment/FlaredSkirt.h"

namespace {

const figment::tools::ToolMain kTool{"figment-make-skirt"};

// Makes the skirt around `body` and writes it: the exit status.
int makeAndWrite(const figment::TriangleMesh& body, const figment::FlaredSkirtOptions& options,
                 const std::string& output) {
  const figment::FlaredSkirt skirt = figment::makeFlaredSkirt(body, options);
  figment::exportObj(skirt.mesh, output);
  std::printf(
      "%s: %s: %zu vertices, %zu triangles, %.3f m^2; waist at %.3f m (%.3f m round, waistband %.3f m), "
      "hem at %.3f m\n",
      kTool.program().c_str(), output.c_str(), skirt.mesh.vertices.size(), skirt.mesh.triangles.size(), skirt.area,
      skirt.waistHeight, skirt.waistPerimeter, skirt.waistbandPerimeter, skirt.hemHeight);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Generates a flared skirt around a body's waist and writes it as a Wavefront OBJ.", kTool.program()};
  figment::tools::BodyInput body;
  std::string output;
  figment::FlaredSkirtOptions options;
  figment::tools::addBodyOptions(app, body);
  app.add_option("-o,--output", output, "OBJ file to write")->required();
  app.add_option("--waist-clearance", options.waistClearance, "gap between waistband and waist, m")
      ->capture_default_str();
  app.add_option("--length", options.length, "waistband to hem, m")->capture_default_str();
  app.add_option("--flare", options.flare, "how much further out the hem lies than the waistband, m")
      ->capture_default_str();
  app.add_option("--rows", options.rows, "rings of quads")->capture_default_str();
  app.add_option("--columns", options.columns, "vertices around a ring")->capture_default_str();
  if (const int status = kTool.parse(app, argc, argv); status >= 0) return status;
  return kTool.withBody(body, [&](const figment::TriangleMesh& bodyMesh, const std::string&) {
    return makeAndWrite(bodyMesh, options, output);
  });
}
