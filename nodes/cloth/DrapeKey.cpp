#include "nodes/cloth/DrapeKey.h"

#include <Inventor/fields/SoMFFloat.h>
#include <Inventor/fields/SoMFInt32.h>
#include <Inventor/fields/SoMFNode.h>
#include <Inventor/fields/SoMFRotation.h>
#include <Inventor/fields/SoMFVec2f.h>
#include <Inventor/fields/SoMFVec3f.h>
#include <Inventor/fields/SoSFBool.h>
#include <Inventor/fields/SoSFDouble.h>
#include <Inventor/fields/SoSFEnum.h>
#include <Inventor/fields/SoSFFloat.h>
#include <Inventor/fields/SoSFInt32.h>
#include <Inventor/fields/SoSFNode.h>
#include <Inventor/fields/SoSFRotation.h>
#include <Inventor/fields/SoSFVec3f.h>
#include <Inventor/lists/SoFieldList.h>
#include <Inventor/misc/SoChildList.h>
#include <Inventor/nodes/SoNode.h>
#include <dlfcn.h>

#include <cinttypes>
#include <cstdio>
#include <filesystem>
#include <set>
#include <system_error>

#include "io/Fnv1a.h"
#include "nodes/body/MeshFile.h"
#include "nodes/cloth/ClothEngine.h"
#include "nodes/cloth/EngineAsk.h"
#include "sim/core/TriangleMesh.h"

namespace figment {

namespace {

class KeyWriter {
 public:
  std::string text = "figment-drape-key 1\n";

  void line(const std::string& name, const std::string& value) { text += name + "=" + value + "\n"; }
  // Small values as their bytes in hex, large ones as their size and two digests.
  void bytes(const std::string& name, const void* data, std::size_t size) {
    char hex[40];
    std::string value;
    if (size <= 32) {
      const auto* b = static_cast<const unsigned char*>(data);
      for (std::size_t i = 0; i < size; ++i) std::snprintf(hex, sizeof hex, "%02x", b[i]), value += hex;
    } else {
      Fnv1a a, b(0x9e3779b97f4a7c15ull);
      a.addBytes(data, size), b.addBytes(data, size);
      std::snprintf(hex, sizeof hex, "%016" PRIx64 "%016" PRIx64, a.value(), b.value());
      value = std::to_string(size) + ":" + hex;
    }
    line(name, value);
  }
  template <class T>
  void value(const std::string& name, const T& v) {
    bytes(name, &v, sizeof v);
  }
  // A file as its path, size and modification time (an unreadable one as its path alone).
  void file(const std::string& name, const std::string& path) {
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    const auto time = std::filesystem::last_write_time(path, ec).time_since_epoch().count();
    if (ec) return line(name, path + " (unreadable)");
    line(name, path + ' ' + std::to_string(size) + ' ' + std::to_string(time));
  }
};

void addNode(KeyWriter& key, const std::string& where, SoNode* node, std::set<const SoNode*>& seen);

// One field, by type: numbers as their bits, nodes by their contents, the rest as text.
void addField(KeyWriter& key, const std::string& name, const SoField& field, std::set<const SoNode*>& seen) {
  const SoType type = field.getTypeId();
  if (type == SoSFFloat::getClassTypeId()) return key.value(name, static_cast<const SoSFFloat&>(field).getValue());
  if (type == SoSFDouble::getClassTypeId()) return key.value(name, static_cast<const SoSFDouble&>(field).getValue());
  if (type == SoSFInt32::getClassTypeId()) return key.value(name, static_cast<const SoSFInt32&>(field).getValue());
  if (type == SoSFEnum::getClassTypeId()) return key.value(name, static_cast<const SoSFEnum&>(field).getValue());
  if (type == SoSFBool::getClassTypeId()) return key.value(name, static_cast<const SoSFBool&>(field).getValue());
  if (type == SoSFVec3f::getClassTypeId()) return key.value(name, static_cast<const SoSFVec3f&>(field).getValue());
  if (type == SoSFRotation::getClassTypeId())
    return key.bytes(name, static_cast<const SoSFRotation&>(field).getValue().getValue(), 4 * sizeof(float));
  if (type == SoMFVec3f::getClassTypeId()) {
    const auto& f = static_cast<const SoMFVec3f&>(field);
    return key.bytes(name, f.getValues(0), f.getNum() * sizeof(SbVec3f));
  }
  if (type == SoMFVec2f::getClassTypeId()) {
    const auto& f = static_cast<const SoMFVec2f&>(field);
    return key.bytes(name, f.getValues(0), f.getNum() * sizeof(SbVec2f));
  }
  if (type == SoMFInt32::getClassTypeId()) {
    const auto& f = static_cast<const SoMFInt32&>(field);
    return key.bytes(name, f.getValues(0), f.getNum() * sizeof(int32_t));
  }
  if (type == SoMFFloat::getClassTypeId()) {
    const auto& f = static_cast<const SoMFFloat&>(field);
    return key.bytes(name, f.getValues(0), f.getNum() * sizeof(float));
  }
  if (type == SoMFRotation::getClassTypeId()) {
    const auto& f = static_cast<const SoMFRotation&>(field);
    for (int i = 0; i < f.getNum(); ++i) key.bytes(name + "[" + std::to_string(i) + "]", f[i].getValue(), 16);
    return key.line(name + ".count", std::to_string(f.getNum()));
  }
  if (type == SoSFNode::getClassTypeId())
    return addNode(key, name, static_cast<const SoSFNode&>(field).getValue(), seen);
  if (type == SoMFNode::getClassTypeId()) {
    const auto& f = static_cast<const SoMFNode&>(field);
    for (int i = 0; i < f.getNum(); ++i) addNode(key, name + "[" + std::to_string(i) + "]", f[i], seen);
    return;
  }
  SbString text;
  const_cast<SoField&>(field).get(text);  // Coin's get() is not const; it only writes the value out
  key.line(name, text.getString());
}

void addFields(KeyWriter& key, const std::string& where, const SoFieldContainer& container,
               std::set<const SoNode*>& seen) {
  SoFieldList fields;
  container.getFields(fields);
  for (int i = 0; i < fields.getLength(); ++i) {
    SbName name;
    container.getFieldName(fields[i], name);
    addField(key, where + "." + name.getString(), *fields[i], seen);
  }
}

void addNode(KeyWriter& key, const std::string& where, SoNode* node, std::set<const SoNode*>& seen) {
  if (!node) return key.line(where, "NULL");
  if (!seen.insert(node).second) return key.line(where, "seen");  // a shared node, counted once
  key.line(where, node->getTypeId().getName().getString());
  addFields(key, where, *node, seen);
  if (node->isOfType(MeshFile::getClassTypeId())) {  // the surface the file gave, not only its name
    const TriangleMesh& surface = static_cast<const MeshFile*>(node)->collisionSurface();
    key.bytes(where + ".surface.vertices", surface.vertices.data(), surface.vertices.size() * sizeof(Vec3));
    key.bytes(where + ".surface.triangles", surface.triangles.data(), surface.triangles.size() * sizeof(Triangle));
    return;  // its children are its own drawing of that surface
  }
  if (const SoChildList* children = node->getChildren())
    for (int i = 0; i < children->getLength(); ++i) addNode(key, where + "/" + std::to_string(i), (*children)[i], seen);
}

// The file that holds this code: the node library (libfigment_nodes.so), whatever program
// loaded it (figment-view, a test, python3 under pivy); "" when the loader cannot say.
std::string nodeLibrary() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<const void*>(&drapeKey), &info) == 0 || !info.dli_fname) return "";
  std::error_code ec;
  const std::filesystem::path file = std::filesystem::canonical(info.dli_fname, ec);
  return ec ? std::string(info.dli_fname) : file.string();
}

}  // namespace

std::string drapeKey(const ClothEngine& engine, const std::string& scriptPath) {
  KeyWriter key;
  const std::string library = nodeLibrary();
  if (library.empty())
    key.line("library", __DATE__ " " __TIME__);
  else
    key.file("library", library);
  std::set<const SoNode*> seen;
  addFields(key, "engine", engine, seen);
  // The step that runs, where the fields' value is not it (an explicit integrator's
  // unwritten timeStep): a written 0.05 and the unwritten default differ.
  key.value("step that runs", engine.timeStepSeconds());
  if (!scriptPath.empty()) key.file("script", scriptPath);
  if (engine.tolerance.getValue() > 0.0) key.file("tradeoff table", tradeoffTablePath());
  return key.text;
}

}  // namespace figment
