#pragma once
// Workers' answers kept in the server's memory by their kind and ETag, the least recently
// used dropped past a byte bound: a repeated request is answered without a worker. Each
// entry is typed by its job kind (serve/workers/JobKind.h): a rendered image (PNG or GLB) or a
// fit's advice (JSON); a lookup of one kind never finds the other's.

#include <cstddef>
#include <list>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <utility>

#include "serve/workers/JobKind.h"

namespace figment::serve {

class ImageCache {
 public:
  explicit ImageCache(size_t maxBytes) : maxBytes_(maxBytes) {}

  std::shared_ptr<const std::string> find(JobKind kind, const std::string& tag);
  void store(JobKind kind, const std::string& tag, std::shared_ptr<const std::string> answer);
  size_t bytes() const;

 private:
  using Key = std::pair<JobKind, std::string>;  // kind, tag
  using Entry = std::pair<Key, std::shared_ptr<const std::string>>;
  mutable std::mutex mutex_;
  std::list<Entry> entries_;  // most recently used first
  std::map<Key, std::list<Entry>::iterator> byKey_;
  size_t bytes_ = 0;
  size_t maxBytes_;
};

}  // namespace figment::serve
