// Medians and quantiles of tiny literal samples whose answers are known.
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "bench/Statistics.h"

using namespace figment::bench;

namespace {

TEST(Statistics, MedianOfOddAndEvenCountsInAnyOrder) {
  EXPECT_DOUBLE_EQ(median({3, 1, 2}), 2.0);
  EXPECT_DOUBLE_EQ(median({4, 1, 3, 2}), 2.5);
  EXPECT_DOUBLE_EQ(median({7}), 7.0);
  EXPECT_DOUBLE_EQ(median({1, 2, 1000}), 2.0);  // one noisy sample does not move it
  EXPECT_THROW(median({}), std::invalid_argument);
}

TEST(Statistics, QuantileInterpolatesBetweenSortedSamples) {
  const std::vector<double> samples = {40, 10, 30, 20, 50};  // sorted: 10 20 30 40 50
  EXPECT_DOUBLE_EQ(quantile(samples, 0.0), 10.0);
  EXPECT_DOUBLE_EQ(quantile(samples, 1.0), 50.0);
  EXPECT_DOUBLE_EQ(quantile(samples, 0.5), 30.0);
  EXPECT_DOUBLE_EQ(quantile(samples, 0.9), 46.0);  // at 3.6: 40 + 0.6 (50 - 40)
  EXPECT_DOUBLE_EQ(quantile(samples, 2.0), 50.0);  // q is clamped to [0, 1]
  EXPECT_THROW(quantile({}, 0.5), std::invalid_argument);
}

}  // namespace
