#pragma once
// Reads back what ByteWriter wrote, value by value; each read says false, and leaves the
// value alone, when the bytes run out, so damaged input is found out, never read past.

#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

namespace figment {

class ByteReader {
 public:
  // Reads from `bytes`, which must outlive the reader.
  explicit ByteReader(const std::vector<unsigned char>& bytes) : bytes_(bytes) {}

  template <class T>
  bool get(T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    if (left() < sizeof(T)) return false;
    std::memcpy(&value, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return true;
  }
  template <class T>
  bool getArray(std::vector<T>& values) {
    static_assert(std::is_trivially_copyable_v<T>);
    std::uint64_t count = 0;
    if (!get(count) || count > left() / sizeof(T)) return false;
    values.resize(count);
    if (count > 0) std::memcpy(values.data(), bytes_.data() + at_, count * sizeof(T));
    at_ += count * sizeof(T);
    return true;
  }
  bool getText(std::string& text) {
    std::uint64_t size = 0;
    if (!get(size) || size > left()) return false;
    text.assign(reinterpret_cast<const char*>(bytes_.data() + at_), size);
    at_ += size;
    return true;
  }
  // Whether every byte has been read: a record followed by more is damaged too.
  bool done() const { return at_ == bytes_.size(); }

 private:
  std::size_t left() const { return bytes_.size() - at_; }

  const std::vector<unsigned char>& bytes_;
  std::size_t at_ = 0;
};

}  // namespace figment
