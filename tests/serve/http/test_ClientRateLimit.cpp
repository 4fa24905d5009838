// Renders per client: a burst, then one a 1/rate seconds; clients apart; off at rate 0.
// Time is given to the limit, never read from a clock.

#include <gtest/gtest.h>

#include "serve/http/ClientRateLimit.h"

using namespace figment::serve;
using Time = ClientRateLimit::Clock::time_point;

TEST(ClientRateLimit, ABurstThenOneRenderPerPeriodPerClient) {
  ClientRateLimit limit(2.0, 3.0);  // 2 a second, 3 at once
  const Time t0{};
  double wait = 0;
  for (int i = 0; i < 3; ++i) EXPECT_TRUE(limit.take("a", t0, wait)) << i;
  EXPECT_FALSE(limit.take("a", t0, wait));
  EXPECT_DOUBLE_EQ(wait, 0.5);             // one token at 2 a second
  EXPECT_TRUE(limit.take("b", t0, wait));  // another client has its own bucket
  EXPECT_FALSE(limit.take("a", t0 + std::chrono::milliseconds(400), wait));
  EXPECT_NEAR(wait, 0.1, 1e-9);
  EXPECT_TRUE(limit.take("a", t0 + std::chrono::milliseconds(500), wait));
  // Long idle refills to the burst, not beyond.
  const Time later = t0 + std::chrono::seconds(100);
  for (int i = 0; i < 3; ++i) EXPECT_TRUE(limit.take("a", later, wait)) << i;
  EXPECT_FALSE(limit.take("a", later, wait));
}

TEST(ClientRateLimit, RateZeroIsNoLimit) {
  ClientRateLimit limit(0.0, 1.0);
  double wait = 0;
  for (int i = 0; i < 100; ++i) EXPECT_TRUE(limit.take("a", Time{}, wait));
}
