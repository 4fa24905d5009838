// figment-measure: a body's measurements as a tape measures them (ISO 8559-1 names,
// sim/body/BodyMeasurements.h), in metres.
//   figment-measure MESH [--json] [--metres-per-unit M] [--up-axis AXIS]
// MESH is found through the model search path and read as a MeshFile reads it (tools/ToolMain.h):
// human.zae, a body figment-body made, any standing body assimp reads. Prints "key value" lines,
// or one JSON object with --json. Any error is one line on stderr and exit status 1.

#include <cstdio>
#include <string>

#include "ToolMain.h"
#include "sim/body/BodyMeasurements.h"

namespace {

const figment::tools::ToolMain kTool{"figment-measure"};

void print(const figment::BodyMeasurements& m, bool json) {
  const auto named = m.named();
  if (!json) {
    for (const auto& [key, value] : named) std::printf("%-16s %.4f m\n", key.c_str(), value);
    return;
  }
  std::printf("{");
  for (size_t i = 0; i < named.size(); ++i)
    std::printf("%s\"%s\": %.5f", i ? ", " : "", named[i].first.c_str(), named[i].second);
  std::printf("}\n");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Measures a standing body as a tape measure would (stature, girths, lengths; metres).", kTool.program()};
  figment::tools::BodyInput body;
  bool json = false;
  figment::tools::addBodyOptions(app, body);
  app.add_option("mesh", body.name, "the body's mesh file (replaces --body)");
  app.add_flag("--json", json, "print one JSON object, keys stature, bust_girth, ...");
  if (const int status = kTool.parse(app, argc, argv); status >= 0) return status;
  return kTool.withBody(body, [&](const figment::TriangleMesh& mesh, const std::string&) {
    print(figment::measureBody(mesh), json);
    return 0;
  });
}
