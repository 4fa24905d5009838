#pragma once
// figment-view --stats: what a render did, as JSON.

#include "viewer/ViewOptions.h"

#include <string>
#include <vector>

class ClothEngine;

namespace figment::viewer {

// Writes, atomically (see writeAtomically):
//   {"scene": ..., "garments": [{"name", "triangles", "iterations", "simulated_s",
//    "wall_s", "at_rest"}, ...], "render_wall_s": ..., "size": [w, h]}
// with one garment per engine, named by its DEF name. Returns "" or the error.
std::string writeStatsJson(const std::string& path, const std::string& scene,
                           const std::vector<ClothEngine*>& engines, double renderWallSeconds,
                           const ImageSize& size);

}  // namespace figment::viewer
