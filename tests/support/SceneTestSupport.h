#pragma once
// Helpers shared by the node tests: Coin set-up, reading and writing .iv text, and
// small mesh files in a temporary folder.

#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/SoOutput.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/actions/SoWriteAction.h>
#include <Inventor/errors/SoDebugError.h>
#include <Inventor/errors/SoReadError.h>
#include <Inventor/nodes/SoSeparator.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "nodes/Init.h"
#include "support/TempDir.h"

namespace figment::test {

// Coin and the node kit, once per test program.
inline void initCoin() {
  figment::init();
}

// A root that unrefs itself.
struct Unref {
  void operator()(SoNode* node) const { node->unref(); }
};
using SceneRoot = std::unique_ptr<SoSeparator, Unref>;

// Collects Coin's read errors (or debug errors) while alive, restoring the handler after.
class CapturedErrors {
 public:
  CapturedErrors() {
    readHandler_ = SoReadError::getHandlerCallback();
    readData_ = SoReadError::getHandlerData();
    debugHandler_ = SoDebugError::getHandlerCallback();
    debugData_ = SoDebugError::getHandlerData();
    SoReadError::setHandlerCallback(collect, this);
    SoDebugError::setHandlerCallback(collect, this);
  }
  ~CapturedErrors() {
    SoReadError::setHandlerCallback(readHandler_, readData_);
    SoDebugError::setHandlerCallback(debugHandler_, debugData_);
  }
  CapturedErrors(const CapturedErrors&) = delete;
  CapturedErrors& operator=(const CapturedErrors&) = delete;

  std::vector<std::string> messages;
  std::string all() const {
    std::string out;
    for (const auto& m : messages) out += m + "\n";
    return out;
  }

 private:
  static void collect(const SoError* error, void* self) {
    static_cast<CapturedErrors*>(self)->messages.emplace_back(error->getDebugString().getString());
  }
  SoErrorCB* readHandler_;
  void* readData_;
  SoErrorCB* debugHandler_;
  void* debugData_;
};

inline SceneRoot readString(const std::string& text) {
  SoInput in;
  in.setBuffer(text.data(), text.size());
  SoSeparator* root = SoDB::readAll(&in);
  if (root) root->ref();
  return SceneRoot(root);
}

inline SceneRoot readFile(const std::string& path) {
  SoInput in;
  if (!in.openFile(path.c_str(), TRUE)) return SceneRoot(nullptr);
  SoSeparator* root = SoDB::readAll(&in);
  if (root) root->ref();
  return SceneRoot(root);
}

inline std::string writeString(SoNode* root) {
  SoOutput out;
  out.setBuffer(std::malloc(1024), 1024, std::realloc);
  SoWriteAction write(&out);
  write.apply(root);
  void* buffer = nullptr;
  size_t size = 0;
  out.getBuffer(buffer, size);
  std::string text(static_cast<const char*>(buffer), size);
  std::free(buffer);
  return text;
}

// Sets $FIGMENT_MODEL_PATH for the scope, then restores what was there.
class ScopedModelPath {
 public:
  explicit ScopedModelPath(const std::string& folders) {
    if (const char* old = std::getenv("FIGMENT_MODEL_PATH")) previous_ = old;
    ::setenv("FIGMENT_MODEL_PATH", folders.c_str(), 1);
  }
  ~ScopedModelPath() {
    if (previous_)
      ::setenv("FIGMENT_MODEL_PATH", previous_->c_str(), 1);
    else
      ::unsetenv("FIGMENT_MODEL_PATH");
  }
  ScopedModelPath(const ScopedModelPath&) = delete;
  ScopedModelPath& operator=(const ScopedModelPath&) = delete;

 private:
  std::optional<std::string> previous_;
};

// The first node of `type` under `root` (inactive Switch children included).
template <class T>
T* find(SoNode* root, const char* name = nullptr) {
  SoSearchAction search;
  search.setType(T::getClassTypeId());
  if (name) search.setName(name);
  search.setSearchingAll(TRUE);
  search.apply(root);
  return search.getPath() ? static_cast<T*>(search.getPath()->getTail()) : nullptr;
}

// A closed unit cube, [0,1]^3, 8 vertices and 12 triangles, faces counter-clockwise
// from outside; in centimetres when `scale` is 100.
inline std::string cubeObj(double scale = 1.0) {
  std::string s = "# unit cube\n";
  for (int i = 0; i < 8; ++i)
    s += "v " + std::to_string((i & 1) * scale) + " " + std::to_string(((i >> 1) & 1) * scale) + " " +
         std::to_string(((i >> 2) & 1) * scale) + "\n";
  // Quads by vertex number (1-based): -x, +x, -y, +y, -z, +z.
  s += "f 1 5 7 3\nf 2 4 8 6\nf 1 2 6 5\nf 3 7 8 4\nf 1 3 4 2\nf 5 6 8 7\n";
  return s;
}

// A flat n x n grid of cloth `size` wide at height y, centred on (cx, cz), as .iv text
// for a Coordinate3's points and a face set's coordIndex.
struct Grid {
  std::string points, coordIndex;
  int numPoints = 0, numTriangles = 0;
};
inline Grid grid(int n, double size, double y, double cx = 0.0, double cz = 0.0) {
  Grid g;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      g.points += std::to_string(cx - size / 2 + size * i / (n - 1)) + " " + std::to_string(y) + " " +
                  std::to_string(cz - size / 2 + size * j / (n - 1)) + ",\n";
    }
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const int a = j * n + i;
      g.coordIndex += std::to_string(a) + " " + std::to_string(a + n) + " " + std::to_string(a + n + 1) + " " +
                      std::to_string(a + 1) + " -1,\n";
    }
  g.numPoints = n * n;
  g.numTriangles = 2 * (n - 1) * (n - 1);
  return g;
}

}  // namespace figment::test
