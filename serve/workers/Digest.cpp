#include "serve/workers/Digest.h"

#include <dlfcn.h>

#include <cstdio>
#include <fstream>
#include <iterator>

#include "nodes/Init.h"

namespace figment::serve {

namespace {

constexpr std::uint64_t kFnvPrime = 0x100000001b3ull;

std::string fileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

Digest& Digest::add(std::string_view bytes) {
  for (unsigned char c : bytes) {
    a_ = (a_ ^ c) * kFnvPrime;
    b_ = (b_ ^ static_cast<unsigned char>(c ^ 0x5a)) * kFnvPrime;
  }
  // The length too, so "ab" + "c" and "a" + "bc" differ.
  const std::uint64_t n = bytes.size();
  for (int i = 0; i < 8; ++i) a_ = (a_ ^ ((n >> (8 * i)) & 0xff)) * kFnvPrime;
  return *this;
}

std::string Digest::hex() const {
  char text[33];
  std::snprintf(text, sizeof text, "%016llx%016llx", static_cast<unsigned long long>(a_),
                static_cast<unsigned long long>(b_));
  return text;
}

std::string Digest::buildDigest() {
  Digest digest;
  digest.add(fileBytes("/proc/self/exe"));
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&figment::init), &info) && info.dli_fname) digest.add(fileBytes(info.dli_fname));
  return digest.hex();
}

}  // namespace figment::serve
