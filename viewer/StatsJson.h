#pragma once
// figment-view --stats: what a render did, as JSON.

#include <string>
#include <vector>

#include "session/SceneSession.h"
#include "viewer/ViewOptions.h"

namespace figment::viewer {

// Writes, atomically (see writeAtomically):
//   {"scene": ..., "garments": [{"name", "triangles", "iterations", "simulated_s",
//    "wall_s", "at_rest", "method": {...}, "body": {"kind", ...}}, ...],
//    "render_wall_s": ..., "size": [w, h]}
// with one garment per engine drape, named by its engine's DEF name. Returns "" or the
// error.
std::string writeStatsJson(const std::string& path, const std::string& scene,
                           const std::vector<session::EngineDrape>& drapes, double renderWallSeconds,
                           const ImageSize& size);

}  // namespace figment::viewer
