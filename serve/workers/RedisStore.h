#pragma once
// A shared cache store (io/SharedCacheStore.h) in Redis: each entry one string value under
// "figment:" and its name ("figment:drape:<digest>", "figment:image:<etag>"), written with
// an expiry, so that Redis's `volatile-lru` eviction (deploy/redis.conf) bounds the cache
// by `maxmemory` and never takes the work queue's keys, which have none. Redis away: a
// miss, and nothing kept.

#include <memory>

#include "io/SharedCacheStore.h"
#include "serve/workers/RedisConnection.h"

namespace figment::serve {

class RedisStore : public SharedCacheStore {
 public:
  static constexpr const char* kPrefix = "figment:";
  static constexpr long kDefaultTtl = 30L * 24 * 3600;  // s: a month unread and an entry goes

  RedisStore(std::shared_ptr<RedisConnection> redis, long ttlSeconds = kDefaultTtl);

  std::optional<std::string> get(const std::string& name) const override;
  bool put(const std::string& name, const std::string& bytes) const override;
  void remove(const std::string& name) const override;
  // Whether an entry is kept under `name`.
  bool contains(const std::string& name) const;

 private:
  std::shared_ptr<RedisConnection> redis_;
  long ttl_;
};

}  // namespace figment::serve
