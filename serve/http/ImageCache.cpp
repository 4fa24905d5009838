#include "serve/http/ImageCache.h"

namespace figment::serve {

std::shared_ptr<const std::string> ImageCache::find(JobKind kind, const std::string& tag) {
  std::lock_guard lock(mutex_);
  auto it = byKey_.find({kind, tag});
  if (it == byKey_.end()) return nullptr;
  entries_.splice(entries_.begin(), entries_, it->second);
  return it->second->second;
}

void ImageCache::store(JobKind kind, const std::string& tag, std::shared_ptr<const std::string> answer) {
  if (!answer || answer->size() > maxBytes_) return;
  std::lock_guard lock(mutex_);
  const Key key{kind, tag};
  if (byKey_.count(key)) return;
  bytes_ += answer->size();
  entries_.emplace_front(key, std::move(answer));
  byKey_[key] = entries_.begin();
  while (bytes_ > maxBytes_) {
    bytes_ -= entries_.back().second->size();
    byKey_.erase(entries_.back().first);
    entries_.pop_back();
  }
}

size_t ImageCache::bytes() const {
  std::lock_guard lock(mutex_);
  return bytes_;
}

}  // namespace figment::serve
