#pragma once
// figment-view --stats: what a render did, as JSON.

#include <string>
#include <vector>

#include "session/EngineFit.h"
#include "session/SceneSession.h"
#include "viewer/ViewOptions.h"

namespace figment::viewer {

// Writes, atomically (see writeAtomically):
//   {"scene": ..., "garments": [{"name", and the engine's last drape as
//    io/DrapeReportJson.h writes it: "triangles", "iterations", ..., "method": {...},
//    "body": {"kind", ...}}, ...], "render_wall_s": ..., "size": [w, h]}
// with one garment per engine, named by its DEF name. A garment with a fit
// in `fits` (session/EngineFit.h) has "fit": {"catalogue", "text", "regions": {REGION:
// {"stretch_pct", "max_stretch_pct", "ease_mm", "girth_ease_cm", "pressure_kpa"[,
// "verdict"]}}}, as figment-size --json gives them. Returns "" or the error.
std::string writeStatsJson(const std::string& path, const std::string& scene, const std::vector<ClothEngine*>& engines,
                           const std::vector<session::EngineFit>& fits, double renderWallSeconds,
                           const ImageSize& size);

}  // namespace figment::viewer
