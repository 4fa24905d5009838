#include "ToolMain.h"

#include "io/MeshImport.h"

#include <cstdio>
#include <exception>
#include <stdexcept>

namespace figment::tools {

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

int ToolMain::withBody(const std::string& bodyName, const std::vector<std::string>& exclude,
                       const std::function<int(const TriangleMesh& body, const std::string& bodyPath)>& work) const {
  const std::string bodyPath = findModelFile(bodyName);
  if (bodyPath.empty())
    return fail(bodyName + ": not found (searched the working directory, $FIGMENT_MODEL_PATH, /usr/share/assimp/models)");
  try {
    ImportOptions options;
    options.exclude = exclude;
    return work(importMesh(bodyPath, options).mesh, bodyPath);
  } catch (const std::runtime_error& error) {  // the importer's and exporter's messages start with the path
    return fail(error.what());
  } catch (const std::exception& error) {
    return fail(bodyPath + ": " + error.what());
  }
}

}  // namespace figment::tools
