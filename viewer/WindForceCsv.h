#pragma once
// figment-view --wind-force: the wind's total force on each garment over simulated time,
// as CSV, for charts of the paper's Figure 2.2.

#include <string>
#include <vector>

#include "session/DrapeRecorder.h"
#include "session/SceneSession.h"

namespace figment::viewer {

// Writes, atomically (see writeAtomically), one row per wind sample of each engine, in
// scene order:
//   engine,time_s,pressure_Pa,phase_rad,force_x_N,force_y_N,force_z_N,force_N
// (engine: its DEF name; force_N = |force|). Returns "" or the error.
std::string writeWindForceCsv(const std::string& path, const std::vector<ClothEngine*>& engines,
                              const session::DrapeRecorder& recorder);

}  // namespace figment::viewer
