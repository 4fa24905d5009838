#pragma once
// Reads a mesh file (Collada, .zae, OBJ, PLY, ... anything assimp reads) into the
// scene frame: metres, y up. Bodies and garments both come in through here.

#include <filesystem>
#include <string>
#include <vector>

#include "io/UpAxis.h"
#include "sim/core/TriangleMesh.h"

namespace figment {

struct ImportOptions {
  double metresPerUnit = 1.0;        // scale applied to the file's coordinates
  UpAxis upAxis = UpAxis::Y;         // the file's up axis; rotated onto +y
  std::vector<std::string> exclude;  // names of meshes in the file to leave out
  bool mergeByPosition = true;       // weld vertices split along texture seams
};

struct ImportedMesh {
  TriangleMesh mesh;                   // triangulated, in metres, y up
  std::vector<std::string> meshNames;  // names of the meshes taken from the file
};

// Throws std::runtime_error("<path>: <reason>") when the file is missing or unreadable.
ImportedMesh importMesh(const std::string& path, const ImportOptions& options = {});

// Finds a model file named `name`: as given when it is absolute or exists relative to
// the working directory; else in each folder of $FIGMENT_MODEL_PATH (colon separated),
// then in `sceneDir`, then in the standard Debian location of assimp-testmodels
// (/usr/share/assimp/models and its subfolders). Returns "" when not found.
std::string findModelFile(const std::string& name, const std::string& sceneDir = {});

// The folders of $FIGMENT_MODEL_PATH (colon separated, empty entries skipped), in order.
std::vector<std::filesystem::path> modelPathFolders();

}  // namespace figment
