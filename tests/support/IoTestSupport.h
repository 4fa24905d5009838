#pragma once
// Helpers for the io tests: a temporary folder, a scoped environment variable, the default body.

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "io/MeshImport.h"
#include "support/TempDir.h"

namespace figment::test {

// Sets (or unsets, with nullopt) an environment variable for the scope, then restores it.
class ScopedEnvironment {
 public:
  ScopedEnvironment(const char* name, std::optional<std::string> value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    if (value)
      ::setenv(name, value->c_str(), 1);
    else
      ::unsetenv(name);
  }
  ~ScopedEnvironment() {
    if (old_)
      ::setenv(name_, old_->c_str(), 1);
    else
      ::unsetenv(name_);
  }
  ScopedEnvironment(const ScopedEnvironment&) = delete;
  ScopedEnvironment& operator=(const ScopedEnvironment&) = delete;

 private:
  const char* name_;
  std::optional<std::string> old_;
};

// The default body (Debian's assimp-testmodels), "" when it is not installed.
inline std::string defaultBodyPath() {
  const ScopedEnvironment noModelPath("FIGMENT_MODEL_PATH", std::nullopt);
  return findModelFile("human.zae");
}

}  // namespace figment::test
