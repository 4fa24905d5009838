#pragma once
// A fit map as a scene figment-view renders (docs/sizes.md): the body (a MeshFile of an OBJ
// beside the scene) and the draped garment as an IndexedFaceSet coloured per vertex by its
// band (sim/fit/FitMap.h), under the lights of the shipped scenes. Coin's text, written
// without Coin.

#include <string>
#include <vector>

#include "sim/core/TriangleMesh.h"

namespace figment {

// Writes `path` (.iv), whole or not at all: `garment` (draped positions) with `bands` (one
// per vertex, 0 to kFitMapBands - 1), and the body read from `bodyFile` (a name beside
// the scene). Throws std::runtime_error("<path>: <reason>").
void writeFitMapScene(const std::string& path, const TriangleMesh& garment, const std::vector<int>& bands,
                      const std::string& bodyFile);

}  // namespace figment
