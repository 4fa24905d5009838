#include "serve/http/ClientRateLimit.h"

#include <algorithm>

namespace figment::serve {

namespace {

constexpr size_t kMaxClients = 10000;  // buckets kept; full ones are dropped past it

}  // namespace

bool ClientRateLimit::take(const std::string& client, Clock::time_point now, double& wait) {
  wait = 0;
  if (rate_ <= 0) return true;
  std::lock_guard lock(mutex_);
  if (buckets_.size() >= kMaxClients) forgetIdle(now);
  auto [it, added] = buckets_.try_emplace(client, Bucket{burst_, now});
  Bucket& bucket = it->second;
  const double elapsed = std::chrono::duration<double>(now - bucket.at).count();
  bucket.tokens = std::min(burst_, bucket.tokens + std::max(0.0, elapsed) * rate_);
  bucket.at = now;
  if (bucket.tokens >= 1.0) {
    bucket.tokens -= 1.0;
    return true;
  }
  wait = (1.0 - bucket.tokens) / rate_;
  return false;
}

void ClientRateLimit::forgetIdle(Clock::time_point now) {
  // A bucket that has filled up again holds nothing a new one would not.
  for (auto it = buckets_.begin(); it != buckets_.end();) {
    const double elapsed = std::chrono::duration<double>(now - it->second.at).count();
    it = it->second.tokens + elapsed * rate_ >= burst_ ? buckets_.erase(it) : std::next(it);
  }
}

}  // namespace figment::serve
