#pragma once
// A fresh folder under the system's temporary folder, removed with the object: for
// tests that write files (meshes, scenes, images).

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace figment::test {

class TempDir {
 public:
  TempDir() {
    std::string pattern = (std::filesystem::temp_directory_path() / "figment-test-XXXXXX").string();
    path_ = ::mkdtemp(pattern.data());
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  // Writes `contents` to `name` (folders created as needed) and returns its path.
  std::string file(const std::string& name, const std::string& contents) const {
    const std::filesystem::path p = path_ / name;
    std::filesystem::create_directories(p.parent_path());
    std::ofstream(p) << contents;
    return p.string();
  }

 private:
  std::filesystem::path path_;
};

}  // namespace figment::test
