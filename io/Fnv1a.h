#pragma once
// FNV-1a, 64 bits: a fast digest that ties a file to what it was made from (a
// progressive script to its garment, a cached drape to its inputs). Not cryptographic.

#include <cstdint>
#include <cstring>
#include <string_view>

namespace figment {

class Fnv1a {
 public:
  explicit Fnv1a(std::uint64_t basis = 14695981039346656037ull) : hash_(basis) {}

  template <class T>
  void add(const T& value) {
    unsigned char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    addBytes(bytes, sizeof(T));
  }
  void addBytes(const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) hash_ = (hash_ ^ bytes[i]) * 1099511628211ull;
  }
  void addText(std::string_view text) { addBytes(text.data(), text.size()); }
  std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_;
};

}  // namespace figment
