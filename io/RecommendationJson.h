#pragma once
// A size recommendation (sim/fit/SizeFitter.h) as one JSON object on one line: what
// figment-size --json prints and GET /api/fit answers (docs/sizes.md shows it). Written
// here once so the program and the service cannot drift apart.

#include <string>
#include <vector>

#include "sim/fit/SizeFitter.h"

namespace figment {

// {"recommended": ..., "all_tight": ..., "sizes": {SIZE: {"text", "steps", "warm",
// "at_rest", "regions": {REGION: {...}}}}}, no newline; without "recommended" and
// "all_tight" when the recommendation is empty (one size tried on).
std::string recommendationJson(const Recommendation& recommendation);

// One line per candidate whose drape was still moving when it stopped at `maxTime` s
// ("dress size S was not at rest after 10 s: its fit may still change"): its fit was
// measured where it stopped, which a shopper must be told.
std::vector<std::string> unrestedSizeLines(const Recommendation& recommendation, const std::string& style,
                                           double maxTime);

}  // namespace figment
