#include "io/TargetLibrary.h"

#include <filesystem>

#include "io/MakeHumanFiles.h"

namespace figment {

const MorphTarget* TargetLibrary::find(const std::string& name) {
  const auto known = loaded_.find(name);
  if (known != loaded_.end()) return known->second.get();
  const std::filesystem::path path = std::filesystem::path(dir_) / "targets" / (name + ".target.gz");
  std::error_code error;
  std::unique_ptr<MorphTarget> target;
  if (std::filesystem::is_regular_file(path, error))
    target = std::make_unique<MorphTarget>(readMorphTarget(path.string()));
  return loaded_.emplace(name, std::move(target)).first->second.get();
}

HumanModel loadHumanModel(const std::string& dir, TargetLibrary& library) {
  return HumanModel(readHumanBase(dir), library.lookup());
}

}  // namespace figment
