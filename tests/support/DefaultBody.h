#pragma once
// The default body (human.zae from assimp-testmodels) without its eyes, read once per test
// program, for the tests of garments generated around it.

#include <optional>

#include "io/MeshImport.h"
#include "support/IoTestSupport.h"

namespace figment::test {

// Null when assimp-testmodels is not installed (the tests then skip).
inline const TriangleMesh* defaultBodyWithoutEyes() {
  static const std::optional<TriangleMesh> body = []() -> std::optional<TriangleMesh> {
    const std::string path = defaultBodyPath();
    if (path.empty()) return std::nullopt;
    ImportOptions options;
    options.exclude = {"eyes"};
    return importMesh(path, options).mesh;
  }();
  return body ? &*body : nullptr;
}

}  // namespace figment::test
