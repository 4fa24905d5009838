#pragma once
// A 128-bit digest as 32 hex digits: names an image by its canonical parameters and the
// build that draws it (the strong ETag), and a program's build by its files. Two FNV-1a
// 64-bit hashes with different offsets: a cache's name, not a defence against forgery
// (a forged tag only ever gets its own request's picture back).

#include <cstdint>
#include <string>
#include <string_view>

namespace figment::serve {

class Digest {
 public:
  Digest& add(std::string_view bytes);
  std::string hex() const;

  // The digest of this program's executable and of the node library it drapes with
  // (the drape cache keys on that library too): a rebuild that may draw otherwise gets
  // other ETags. "" parts when a file cannot be read.
  static std::string buildDigest();

 private:
  std::uint64_t a_ = 0xcbf29ce484222325ull;  // FNV-1a's offset basis
  std::uint64_t b_ = 0x84222325cbf29ce4ull;  // the same, halves swapped
};

}  // namespace figment::serve
