#include "serve/workers/RedisStore.h"

namespace figment::serve {

RedisStore::RedisStore(std::shared_ptr<RedisConnection> redis, long ttlSeconds)
    : redis_(std::move(redis)), ttl_(ttlSeconds) {}

std::optional<std::string> RedisStore::get(const std::string& name) const {
  // GETEX renews the expiry: an entry read often stays (Redis 6.2 and later).
  RedisReply reply = redis_->command({"GETEX", kPrefix + name, "EX", std::to_string(ttl_)});
  if (reply.kind != RedisReply::Kind::kString) return std::nullopt;
  return std::move(reply.text);
}

bool RedisStore::put(const std::string& name, const std::string& bytes) const {
  return redis_->command({"SET", kPrefix + name, bytes, "EX", std::to_string(ttl_)}).kind == RedisReply::Kind::kStatus;
}

void RedisStore::remove(const std::string& name) const {
  redis_->command({"DEL", kPrefix + name});
}

bool RedisStore::contains(const std::string& name) const {
  const RedisReply reply = redis_->command({"EXISTS", kPrefix + name});
  return reply.kind == RedisReply::Kind::kInteger && reply.integer > 0;
}

}  // namespace figment::serve
