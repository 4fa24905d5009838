#pragma once
// Renders per client: a token bucket per remote address, `rate` tokens a second up to
// `burst`. Only what reaches a worker takes a token (a cached image or a 304 costs
// nothing), so one client cannot keep the workers to itself. Off when rate is 0.

#include <chrono>
#include <mutex>
#include <string>
#include <unordered_map>

namespace figment::serve {

class ClientRateLimit {
 public:
  using Clock = std::chrono::steady_clock;
  ClientRateLimit(double rate, double burst) : rate_(rate), burst_(burst) {}

  // Takes a token for `client` at `now`; false (and the seconds until one is there in
  // `wait`) when it has none left.
  bool take(const std::string& client, Clock::time_point now, double& wait);

 private:
  struct Bucket {
    double tokens;
    Clock::time_point at;
  };
  void forgetIdle(Clock::time_point now);

  double rate_, burst_;
  std::mutex mutex_;
  std::unordered_map<std::string, Bucket> buckets_;
};

}  // namespace figment::serve
