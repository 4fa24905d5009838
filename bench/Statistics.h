#pragma once
// Summaries for benchmark samples: medians, not means (a noisy neighbour on a shared
// machine shifts a mean, rarely a median).

#include <vector>

namespace figment::bench {

double median(std::vector<double> samples);
// The q-quantile (q in [0, 1]) by linear interpolation between the sorted samples: the
// p90 of a timing is quantile(samples, 0.9). Throws std::invalid_argument for no samples.
double quantile(std::vector<double> samples, double q);

}  // namespace figment::bench
