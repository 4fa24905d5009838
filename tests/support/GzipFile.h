#pragma once
// A gzip file written from text, as MakeHuman ships its targets (*.target.gz).

#include <gtest/gtest.h>
#include <zlib.h>

#include <string>

namespace figment::test {

inline void writeGzip(const std::string& path, const std::string& text) {
  gzFile file = gzopen(path.c_str(), "wb");
  ASSERT_NE(file, nullptr);
  gzwrite(file, text.data(), unsigned(text.size()));
  gzclose(file);
}

}  // namespace figment::test
