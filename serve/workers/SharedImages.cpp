#include "serve/workers/SharedImages.h"

#include <cinttypes>
#include <cstdio>

#include "io/Fnv1a.h"

namespace figment::serve {

namespace {

constexpr std::string_view kMagic = "figment-image 1\n";
constexpr size_t kTagLength = 32;
constexpr size_t kHeaderLength = kMagic.size() + kTagLength + 2 * 16;  // magic, tag, size and checksum in hex

std::string header(const std::string& tag, const std::string& image) {
  Fnv1a sum;
  sum.addText(image);
  char numbers[33];
  std::snprintf(numbers, sizeof numbers, "%016" PRIx64 "%016" PRIx64, std::uint64_t(image.size()), sum.value());
  return std::string(kMagic) + tag + numbers;
}

}  // namespace

std::string SharedImages::encode(const std::string& tag, const std::string& image) {
  return header(tag, image) + image;
}

std::shared_ptr<const std::string> SharedImages::decode(const std::string& tag, const std::string& entry) {
  if (tag.size() != kTagLength || entry.size() < kHeaderLength) return nullptr;
  auto image = std::make_shared<const std::string>(entry.substr(kHeaderLength));
  if (entry.compare(0, kHeaderLength, header(tag, *image)) != 0) return nullptr;
  return image;
}

std::shared_ptr<const std::string> SharedImages::find(JobKind kind, const std::string& tag) const {
  const std::optional<std::string> entry = store_->get(nameOf(kind, tag));
  if (!entry) return nullptr;
  std::shared_ptr<const std::string> image = decode(tag, *entry);
  if (!image) store_->remove(nameOf(kind, tag));  // damaged or foreign: made again and stored anew
  return image;
}

bool SharedImages::store(JobKind kind, const std::string& tag, const std::string& image) const {
  return store_->put(nameOf(kind, tag), encode(tag, image));
}

}  // namespace figment::serve
