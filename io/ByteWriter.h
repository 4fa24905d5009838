#pragma once
// Values appended to a byte string one at a time, in this machine's byte order: how the
// drape cache writes its entries and the engine its record of a run, field by field
// (never a whole struct's bytes, whose padding and layout are the compiler's).

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace figment {

class ByteWriter {
 public:
  // A number, or a fixed array of them, as its bytes.
  template <class T>
  void put(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    append(&value, sizeof(T));
  }
  // A count (uint64), then the elements' bytes.
  template <class T>
  void putArray(const std::vector<T>& values) {
    static_assert(std::is_trivially_copyable_v<T>);
    put(static_cast<std::uint64_t>(values.size()));
    append(values.data(), values.size() * sizeof(T));
  }
  // A length (uint64), then the characters.
  void putText(const std::string& text) {
    put(static_cast<std::uint64_t>(text.size()));
    append(text.data(), text.size());
  }
  std::vector<unsigned char> take() { return std::move(bytes_); }

 private:
  // Byte by byte: GCC 12 warns, wrongly, of an overflow where a range is inserted or
  // copied into a vector just grown, once inlined (-Wstringop-overflow).
  void append(const void* data, std::size_t size) {
    const auto* first = static_cast<const unsigned char*>(data);
    std::copy_n(first, size, std::back_inserter(bytes_));
  }
  std::vector<unsigned char> bytes_;
};

}  // namespace figment
