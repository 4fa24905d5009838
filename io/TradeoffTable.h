#pragma once
// The tradeoff study's table as a file (figment-bench tradeoff writes it,
// docs/tradeoff-table.csv holds the committed one, the build installs it); its rows are
// sim/drape/MethodTable.h's MeasuredConfiguration.
//
// Format: CSV with a header line; columns method, body, progressive, resolution,
// garments, worst_mean_dev_pct_height, total_median_wall_s. `method` is
// INTEGRATOR[+CONTACTS]:DT[:LIMITER:LIMIT_G] (sim/drape/DrapeMethod.h, e.g.
// implicit+penalty:0.05, heun:1.5e-4:clamp:30), body volumes/capsules/triangles/mix,
// progressive off or BEGIN_SHARE:RATE.

#include <string>

#include "sim/drape/MethodTable.h"

namespace figment {

// Throws std::runtime_error naming the file (and line) when it cannot be read.
MethodTable readTradeoffTable(const std::string& path);

}  // namespace figment
