#include "FuzzTempDir.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

namespace figment::fuzz {

std::string enterTempDir(const char* prefix) {
  const char* tmp = std::getenv("TMPDIR");
  std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/" + prefix + "-XXXXXX";
  if (!mkdtemp(pattern.data()) || chdir(pattern.c_str()) != 0) {
    std::perror("fuzz: cannot make a working folder");
    std::abort();
  }
  return pattern;
}

void writeFile(const std::string& name, const uint8_t* data, size_t size) {
  std::ofstream out(name, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  if (!out) {
    std::perror(("fuzz: cannot write " + name).c_str());
    std::abort();
  }
}

void writeFile(const std::string& name, const std::string& text) {
  writeFile(name, reinterpret_cast<const uint8_t*>(text.data()), text.size());
}

}  // namespace figment::fuzz
