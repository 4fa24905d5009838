#include "serve/scene/Wardrobe.h"

#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/misc/SoChildList.h>
#include <Inventor/nodes/SoSeparator.h>

#include <algorithm>
#include <filesystem>

#include "io/GarmentCatalogue.h"
#include "nodes/body/MeshFile.h"
#include "nodes/body/SkeletonJoints.h"
#include "serve/request/ShopperChoices.h"

namespace figment::serve {

namespace {

// The shared nodes as scene text: fixed in code, with ShopperChoices' file names only.
std::string wardrobeText() {
  std::string text =
      "#Inventor V2.1 ascii\nSeparator {\n"
      "  MeshFile { fileName \"human.zae\" collisionExclude \"human-highpolyeyesMesh\" }\n"
      "  File { name \"human-volumes.iv\" }\n";
  for (const GarmentStyle& style : ShopperChoices::styles())
    text += "  MeshFile { fileName \"" + style.pattern + "\" }\n";
  return text + "}\n";
}

// The SkeletonJoints at any depth below `node`, a File's children included (which a
// search action does not enter).
const SkeletonJoints* findJoints(SoNode* node) {
  if (node->isOfType(SkeletonJoints::getClassTypeId())) return static_cast<const SkeletonJoints*>(node);
  SoChildList* children = node->getChildren();
  for (int i = 0; children && i < children->getLength(); ++i)
    if (const SkeletonJoints* joints = findJoints((*children)[i])) return joints;
  return nullptr;
}

}  // namespace

Wardrobe::Wardrobe() = default;

Wardrobe::~Wardrobe() {
  if (root_) root_->unref();
}

std::string Wardrobe::read(const std::string& scenesFolder) {
  if (!std::filesystem::is_regular_file(std::filesystem::path(scenesFolder) / "human-volumes.iv"))
    return scenesFolder + ": no human-volumes.iv (not FIGMENT's scenes folder)";
  const std::string text = wardrobeText();
  SoInput in;
  in.addDirectoryFirst(scenesFolder.c_str());
  in.setBuffer(text.data(), text.size());
  SoSeparator* root = SoDB::readAll(&in);
  if (!root) return "the body or a pattern did not read from " + scenesFolder;
  root_ = root;
  root_->ref();
  // The children in the text's order (no DEF names: Coin's name dictionary is the
  // whole process's): the body, its volumes, then one pattern per style.
  const size_t styles = ShopperChoices::styles().size();
  if (size_t(root->getNumChildren()) != 2 + styles) return "the body or a pattern did not read from " + scenesFolder;
  const auto meshFile = [root](int i) {
    SoNode* node = root->getChild(i);
    return node->isOfType(MeshFile::getClassTypeId()) ? static_cast<MeshFile*>(node) : nullptr;
  };
  body_ = meshFile(0);
  volumes_ = root->getChild(1);
  for (size_t i = 0; i < styles; ++i) patterns_[ShopperChoices::styles()[i].name] = meshFile(int(2 + i));
  if (!body_ || body_->point.getNum() == 0) return "the body did not read from " + scenesFolder;
  for (const auto& [style, pattern] : patterns_)
    if (!pattern || pattern->point.getNum() == 0) return "the " + style + "'s pattern did not read";
  if (!findHeightOrigin()) return "the body's skeleton did not read from " + scenesFolder;
  return readCatalogue(scenesFolder);
}

std::string Wardrobe::readCatalogue(const std::string& scenesFolder) {
  try {
    catalogue_ = std::make_unique<GarmentCatalogue>(scenesFolder + "/catalogue/index.txt");
  } catch (const std::exception& error) {
    return error.what();
  }
  // The service's styles and their default colours are the catalogue's.
  for (const GarmentStyle& style : ShopperChoices::styles()) {
    const CatalogueStyle* sold = catalogue_->style(style.name);
    if (!sold) return scenesFolder + "/catalogue/index.txt: no style " + style.name;
    if (sold->colours.front() != style.defaultColour)
      return scenesFolder + "/catalogue/index.txt: " + style.name + "'s first colour is not " + style.defaultColour;
  }
  return "";
}

bool Wardrobe::findHeightOrigin() {
  const SkeletonJoints* joints = findJoints(volumes_);
  if (!joints || joints->positions.getNum() == 0) return false;
  const SbVec3f root = joints->positions[0];
  float floor = root[1];
  for (int i = 0; i < joints->positions.getNum(); ++i) floor = std::min(floor, joints->positions[i][1]);
  heightOrigin_ = SbVec3f(root[0], floor, root[2]);
  return true;
}

MeshFile* Wardrobe::pattern(const std::string& style) const {
  auto it = patterns_.find(style);
  return it == patterns_.end() ? nullptr : it->second;
}

}  // namespace figment::serve
