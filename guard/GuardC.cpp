#include "guard/GuardC.h"

#include <Inventor/SoDB.h>
#include <Inventor/nodes/SoGroup.h>
#include <Inventor/nodes/SoSeparator.h>

#include <algorithm>
#include <cstring>
#include <exception>
#include <string>

#include "guard/Guard.h"

namespace {

// 1, with `text` copied into `error` as one line, as far as `size` allows.
int refuse(std::string line, char* error, size_t size) {
  for (char& c : line)
    if (c == '\n' || c == '\r') c = ' ';
  if (error && size > 0) {
    const size_t n = std::min(line.size(), size - 1);
    std::memcpy(error, line.data(), n);
    error[n] = '\0';
  }
  return 1;
}

int readInto(const char* path, void* group, char* error, size_t size) {
  if (!path) return refuse("no scene path given", error, size);
  SoDB::init();  // does nothing when the program (pivy on import) has
  auto* into = static_cast<SoNode*>(group);
  if (into && !into->isOfType(SoGroup::getClassTypeId()))
    return refuse("the node to add the scene to is not a group", error, size);
  std::string line;
  SoSeparator* root = figment::guard::readScene(path, line);
  if (!root) return refuse(line, error, size);
  if (into) static_cast<SoGroup*>(into)->addChild(root);
  root->unref();
  return 0;
}

}  // namespace

extern "C" int figment_guard_read_scene(const char* path, void* group, char* error, size_t size) {
  try {
    return readInto(path, group, error, size);
  } catch (const std::exception& e) {
    return refuse(std::string("unexpected error: ") + e.what(), error, size);
  } catch (...) {
    return refuse("unexpected error of an unknown type", error, size);
  }
}

extern "C" int figment_guard_check_shapes(void* root, char* error, size_t size) {
  try {
    if (!root) return refuse("no scene given", error, size);
    const std::string line = figment::guard::checkShapes(static_cast<SoNode*>(root));
    return line.empty() ? 0 : refuse(line, error, size);
  } catch (const std::exception& e) {
    return refuse(std::string("unexpected error: ") + e.what(), error, size);
  } catch (...) {
    return refuse("unexpected error of an unknown type", error, size);
  }
}
