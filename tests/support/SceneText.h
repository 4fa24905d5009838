#pragma once
// Scene text in tests: a shipped scene read whole, and changed in one named place.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace figment::test {

inline std::string readText(const std::filesystem::path& path) {
  std::stringstream text;
  text << std::ifstream(path).rdbuf();
  return text.str();
}

// The first `from` in `text` becomes `to`; a test fails when there is none (the scene it
// changes was edited).
inline void replace(std::string& text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
}

}  // namespace figment::test
