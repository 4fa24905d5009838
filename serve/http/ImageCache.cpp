#include "serve/http/ImageCache.h"

namespace figment::serve {

std::shared_ptr<const std::string> ImageCache::find(const std::string& tag) {
  std::lock_guard lock(mutex_);
  auto it = byTag_.find(tag);
  if (it == byTag_.end()) return nullptr;
  entries_.splice(entries_.begin(), entries_, it->second);
  return it->second->second;
}

void ImageCache::store(const std::string& tag, std::shared_ptr<const std::string> image) {
  if (!image || image->size() > maxBytes_) return;
  std::lock_guard lock(mutex_);
  if (byTag_.count(tag)) return;
  bytes_ += image->size();
  entries_.emplace_front(tag, std::move(image));
  byTag_[tag] = entries_.begin();
  while (bytes_ > maxBytes_) {
    bytes_ -= entries_.back().second->size();
    byTag_.erase(entries_.back().first);
    entries_.pop_back();
  }
}

size_t ImageCache::bytes() const {
  std::lock_guard lock(mutex_);
  return bytes_;
}

}  // namespace figment::serve
