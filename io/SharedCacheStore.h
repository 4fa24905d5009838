#pragma once
// A store of cache entries that several programs, or machines, share (figment-serve keeps
// one in Redis: serve/workers/RedisStore.h), below a cache that keeps its entries locally first
// (DrapeCache's folder, the server's memory). Entries are named by the content they hold
// (digests of their keys) and carry their own checks: the store keeps bytes, the cache
// above it verifies what it reads back and drops what is damaged or foreign.
//
// A store that cannot be reached behaves as an empty one that keeps nothing: a shared
// level speeds things up, it never decides whether an answer can be made.

#include <optional>
#include <string>

namespace figment {

class SharedCacheStore {
 public:
  virtual ~SharedCacheStore() = default;

  // The bytes kept under `name`, or nothing (none kept, or the store unreachable).
  virtual std::optional<std::string> get(const std::string& name) const = 0;
  // Keeps `bytes` under `name`; whether they were kept.
  virtual bool put(const std::string& name, const std::string& bytes) const = 0;
  // Drops the entry under `name`, if any.
  virtual void remove(const std::string& name) const = 0;
};

}  // namespace figment
