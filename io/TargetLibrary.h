#pragma once
// The morph targets of a MakeHuman data folder, read on first use and kept: a body blends
// a few dozen of the folder's hundreds, and a fit makes many bodies from the same ones.

#include <map>
#include <memory>
#include <string>

#include "sim/body/HumanModel.h"

namespace figment {

class TargetLibrary {
 public:
  explicit TargetLibrary(std::string dir) : dir_(std::move(dir)) {}

  // The target `name` (path under targets/, no ".target.gz"), or null when the folder has
  // no such file. Throws std::runtime_error for a file that exists but cannot be read.
  const MorphTarget* find(const std::string& name);
  // As a HumanModel's lookup; the library must outlive the model.
  TargetLookup lookup() {
    return [this](const std::string& name) { return find(name); };
  }

 private:
  std::string dir_;
  std::map<std::string, std::unique_ptr<MorphTarget>> loaded_;  // null: no such file
};

// The model over `dir` (findMakeHumanData) with `library`'s targets.
HumanModel loadHumanModel(const std::string& dir, TargetLibrary& library);

}  // namespace figment
