#include "nodes/SceneFiles.h"

#include <Inventor/SoInput.h>
#include <Inventor/lists/SbStringList.h>

#include <algorithm>
#include <filesystem>

#include "io/MeshImport.h"

namespace figment {

std::vector<std::string> sceneSearchDirectories(SoInput* in) {
  std::vector<std::filesystem::path> dirs;
  std::error_code ec;
  if (in) {
    const char* current = in->getCurFileName();
    if (current && *current && std::filesystem::is_regular_file(current, ec))
      dirs.push_back(std::filesystem::path(current).parent_path());
  }
  const SbStringList& coinDirs = SoInput::getDirectories();
  for (int i = 0; i < coinDirs.getLength(); ++i) dirs.emplace_back(coinDirs[i]->getString());
  std::vector<std::string> out;
  for (const auto& dir : dirs) {
    const std::string absolute = std::filesystem::absolute(dir.empty() ? "." : dir, ec).lexically_normal().string();
    if (std::find(out.begin(), out.end(), absolute) == out.end()) out.push_back(absolute);
  }
  return out;
}

std::string resolveSceneFile(const std::string& name, const std::vector<std::string>& dirs) {
  for (const auto& dir : dirs) {
    std::string path = findModelFile(name, dir);
    if (!path.empty()) return path;
  }
  return findModelFile(name);
}

}  // namespace figment
