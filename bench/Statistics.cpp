#include "Statistics.h"

#include <algorithm>
#include <stdexcept>

namespace figment::bench {

double median(std::vector<double> samples) {
  if (samples.empty()) throw std::invalid_argument("median of no samples");
  std::sort(samples.begin(), samples.end());
  const size_t middle = samples.size() / 2;
  return samples.size() % 2 ? samples[middle] : 0.5 * (samples[middle - 1] + samples[middle]);
}

double quantile(std::vector<double> samples, double q) {
  if (samples.empty()) throw std::invalid_argument("quantile of no samples");
  std::sort(samples.begin(), samples.end());
  const double at = std::clamp(q, 0.0, 1.0) * double(samples.size() - 1);
  const size_t below = size_t(at);
  const size_t above = std::min(below + 1, samples.size() - 1);
  return samples[below] + (at - double(below)) * (samples[above] - samples[below]);
}

}  // namespace figment::bench
