#pragma once
// Rendered images (PNG or GLB) in a shared store (serve/work/RedisStore.h) by their ETag, so an
// image one figment-serve instance made is answered by every other without a worker. An
// entry holds a header before the image: a magic line, the tag it was stored under, the
// image's size and checksum; an entry that is damaged, cut short or stored under another
// tag (foreign) is dropped on reading and the image made again.

#include <memory>
#include <string>

#include "io/SharedCacheStore.h"

namespace figment::serve {

class SharedImages {
 public:
  explicit SharedImages(std::shared_ptr<const SharedCacheStore> store) : store_(std::move(store)) {}

  // The image kept for `tag` (the ETag's 32 hex digits, unquoted), if a sound one is kept.
  std::shared_ptr<const std::string> find(const std::string& tag) const;
  // Keeps `image` under `tag`; whether it was kept.
  bool store(const std::string& tag, const std::string& image) const;

  // The store's name for the entry of `tag`: "image:" and the tag.
  static std::string nameOf(const std::string& tag) { return "image:" + tag; }
  // An entry's bytes, and the image back from them (null when unsound or not `tag`'s).
  static std::string encode(const std::string& tag, const std::string& image);
  static std::shared_ptr<const std::string> decode(const std::string& tag, const std::string& entry);

 private:
  std::shared_ptr<const SharedCacheStore> store_;
};

}  // namespace figment::serve
