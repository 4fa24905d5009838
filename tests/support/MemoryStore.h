#pragma once
// A shared cache store in memory (io/SharedCacheStore.h), as two programs over one Redis
// see it: for the caches' tests without a Redis.

#include <map>
#include <optional>
#include <string>

#include "io/SharedCacheStore.h"

namespace figment::test {

class MemoryStore : public SharedCacheStore {
 public:
  std::optional<std::string> get(const std::string& name) const override {
    auto it = entries.find(name);
    return it == entries.end() ? std::nullopt : std::optional<std::string>(it->second);
  }
  bool put(const std::string& name, const std::string& bytes) const override {
    entries[name] = bytes;
    return true;
  }
  void remove(const std::string& name) const override { entries.erase(name); }
  mutable std::map<std::string, std::string> entries;
};

}  // namespace figment::test
