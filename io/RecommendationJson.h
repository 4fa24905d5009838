#pragma once
// A size recommendation (sim/fit/SizeFitter.h) as one JSON object on one line: what
// figment-size --json prints and GET /api/fit answers (docs/sizes.md shows it). Written
// here once so the program and the service cannot drift apart.

#include <string>

#include "sim/fit/SizeFitter.h"

namespace figment {

// {"recommended": ..., "all_tight": ..., "sizes": {SIZE: {"text", "steps", "warm",
// "at_rest", "regions": {REGION: {...}}}}}, no newline; without "recommended" and
// "all_tight" when the recommendation is empty (one size tried on).
std::string recommendationJson(const Recommendation& recommendation);

}  // namespace figment
