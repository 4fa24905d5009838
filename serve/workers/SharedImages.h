#pragma once
// Rendered images (PNG or GLB) in a shared store (serve/workers/RedisStore.h) by their ETag, so an
// image one figment-serve instance made is answered by every other without a worker; a
// fit's advice is kept the same way in an entry of its own kind ("fit:", not "image:"). An
// entry holds a header before the image: a magic line, the tag it was stored under, the
// image's size and checksum; an entry that is damaged, cut short or stored under another
// tag (foreign) is dropped on reading and the image made again.

#include <memory>
#include <string>

#include "io/SharedCacheStore.h"
#include "serve/workers/JobKind.h"

namespace figment::serve {

class SharedImages {
 public:
  explicit SharedImages(std::shared_ptr<const SharedCacheStore> store) : store_(std::move(store)) {}

  // The answer of `kind` kept for `tag` (the ETag's 32 hex digits, unquoted), if a sound one is kept.
  std::shared_ptr<const std::string> find(JobKind kind, const std::string& tag) const;
  // Keeps `image` (a render's, or a fit's advice) under `tag`; whether it was kept.
  bool store(JobKind kind, const std::string& tag, const std::string& image) const;

  // The store's name for the entry of `tag`: "image:" and the tag for a render, "fit:" and
  // the tag for a fit.
  static std::string nameOf(JobKind kind, const std::string& tag) {
    return (kind == JobKind::kFit ? "fit:" : "image:") + tag;
  }
  // An entry's bytes, and the image back from them (null when unsound or not `tag`'s).
  static std::string encode(const std::string& tag, const std::string& image);
  static std::shared_ptr<const std::string> decode(const std::string& tag, const std::string& entry);

 private:
  std::shared_ptr<const SharedCacheStore> store_;
};

}  // namespace figment::serve
