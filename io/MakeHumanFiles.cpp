// MakeHuman's files. The base mesh is Wavefront OBJ (v, vt, g, f lines; faces index from 1,
// "v/vt"); a target is gzip-compressed text, one "index dx dy dz" a line (zlib's gz* calls).

#include "io/MakeHumanFiles.h"

#include <zlib.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "io/MeshImport.h"

namespace fs = std::filesystem;

namespace figment {

namespace {

bool holdsBase(const fs::path& dir) {
  std::error_code error;
  return fs::is_regular_file(dir / "3dobjs" / "base.obj", error);
}

std::string gunzip(const std::string& path) {
  gzFile file = gzopen(path.c_str(), "rb");
  if (!file) throw std::runtime_error(path + ": cannot be opened");
  std::string text;
  char buffer[1 << 16];
  int n = 0;
  while ((n = gzread(file, buffer, sizeof buffer)) > 0) text.append(buffer, n);
  const bool failed = n < 0;
  gzclose(file);
  if (failed) throw std::runtime_error(path + ": not a readable gzip file");
  return text;
}

// A face's vertex numbers (1-based "v", "v/vt" or "v/vt/vn") as 0-based indices.
std::vector<int> faceIndices(std::istringstream& line, int vertexCount, const std::string& path) {
  std::vector<int> face;
  std::string token;
  while (line >> token) {
    const int index = std::atoi(token.c_str()) - 1;
    if (index < 0 || index >= vertexCount) throw std::runtime_error(path + ": face vertex " + token + " out of range");
    face.push_back(index);
  }
  if (face.size() < 3) throw std::runtime_error(path + ": a face with fewer than 3 vertices");
  return face;
}

}  // namespace

std::string findMakeHumanData() {
  if (const char* dir = std::getenv("FIGMENT_MAKEHUMAN_DIR"); dir && *dir) return holdsBase(dir) ? dir : "";
  for (const fs::path& folder : modelPathFolders())
    if (holdsBase(folder / "makehuman")) return (folder / "makehuman").string();
  return holdsBase(FIGMENT_MAKEHUMAN_DEFAULT_DIR) ? FIGMENT_MAKEHUMAN_DEFAULT_DIR : "";
}

HumanBase readHumanBase(const std::string& dir) {
  const std::string path = (fs::path(dir) / "3dobjs" / "base.obj").string();
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot be opened");
  std::vector<Vec3> all;
  std::vector<std::vector<int>> faces;
  std::string line, group;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string kind;
    fields >> kind;
    if (kind == "v") {
      Vec3 v;
      if (!(fields >> v.x() >> v.y() >> v.z())) throw std::runtime_error(path + ": bad vertex line '" + line + "'");
      all.push_back(v);
    } else if (kind == "g") {
      fields >> group;
    } else if (kind == "f" && group == "body") {
      faces.push_back(faceIndices(fields, int(all.size()), path));
    }
  }
  if (faces.empty()) throw std::runtime_error(path + ": no faces in group 'body'");
  HumanBase base;
  base.fileVertexCount = int(all.size());
  base.fileVertices = all;
  std::vector<int> skinIndex(all.size(), -1);
  for (const std::vector<int>& face : faces) {
    for (int v : face) {
      if (skinIndex[v] >= 0) continue;
      skinIndex[v] = int(base.fileIndex.size());
      base.fileIndex.push_back(v);
      base.skin.vertices.push_back(all[v]);
    }
    for (size_t k = 1; k + 1 < face.size(); ++k)  // a fan: quads become two triangles
      base.skin.triangles.push_back({skinIndex[face[0]], skinIndex[face[k]], skinIndex[face[k + 1]]});
  }
  return base;
}

MorphTarget readMorphTarget(const std::string& path) {
  std::istringstream text(gunzip(path));
  MorphTarget target;
  std::string line;
  while (std::getline(text, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    int index = 0;
    Vec3 offset;
    if (!(fields >> index >> offset.x() >> offset.y() >> offset.z()) || index < 0)
      throw std::runtime_error(path + ": bad line '" + line + "'");
    target.vertices.push_back(index);
    target.offsets.push_back(offset);
  }
  return target;
}

}  // namespace figment
