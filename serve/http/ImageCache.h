#pragma once
// Rendered images kept in the server's memory by their ETag, the least recently used
// dropped past a byte bound: a repeated request is answered without a worker.

#include <cstddef>
#include <list>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>

namespace figment::serve {

class ImageCache {
 public:
  explicit ImageCache(size_t maxBytes) : maxBytes_(maxBytes) {}

  std::shared_ptr<const std::string> find(const std::string& tag);
  void store(const std::string& tag, std::shared_ptr<const std::string> image);
  size_t bytes() const;

 private:
  using Entry = std::pair<std::string, std::shared_ptr<const std::string>>;
  mutable std::mutex mutex_;
  std::list<Entry> entries_;  // most recently used first
  std::unordered_map<std::string, std::list<Entry>::iterator> byTag_;
  size_t bytes_ = 0;
  size_t maxBytes_;
};

}  // namespace figment::serve
