#pragma once
// Summaries for benchmark samples: medians, not means (a noisy neighbour on a shared
// machine shifts a mean, rarely a median).

#include <vector>

namespace figment::bench {

double median(std::vector<double> samples);

}  // namespace figment::bench
