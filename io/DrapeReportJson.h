#pragma once
// A drape's report (sim/drape/DrapeReport.h) as one JSON object on one line: what
// figment-view --stats writes per garment, figment-sew --stats under "drape" and
// figment-bench's drape study per row. Written here once so the programs cannot drift
// apart (docs/interfaces.md lists its keys, under figment-view's --stats).

#include <string>

#include "sim/drape/DrapeReport.h"

namespace figment {

// {"triangles", "iterations", "simulated_s", "wall_s", "at_rest", "cached",
//  "verdict": {"clean", "text", "max_speed_m_s", "max_edge_stretch", ...},
//  "method": {"integrator", "time_step_s", ...}, "body": {"kind", PART: count, ...}
//  [, "picked": {...}: with a tolerance][, "progressive": {...}: a progressive drape]},
// no newline.
std::string drapeReportJson(const DrapeReport& report);

}  // namespace figment
