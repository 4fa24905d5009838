#pragma once
// What every scene a worker builds shares, read once when the worker starts: the default
// body's mesh and shaped collision volumes, each service style's pattern, and the garment
// catalogue's files (catalogue/index.txt, io/GarmentCatalogue.h), which must sell every
// style of ShopperChoices.h with its default colour first. The files are those ShopperChoices.h
// names, found in the scenes folder; nothing here is named by a request.

#include <Inventor/SbVec3f.h>
#include <Inventor/nodes/SoNode.h>

#include <map>
#include <memory>
#include <string>

class MeshFile;

namespace figment {
class GarmentCatalogue;
}

namespace figment::serve {

class Wardrobe {
 public:
  // Both in the .cpp, where GarmentCatalogue is a complete type (its unique_ptr deletes it).
  Wardrobe();
  ~Wardrobe();
  Wardrobe(const Wardrobe&) = delete;
  Wardrobe& operator=(const Wardrobe&) = delete;

  // Reads the body, its volumes and the patterns from `scenesFolder`; "" or one line
  // naming what did not read. Coin and FIGMENT's nodes must be initialised.
  std::string read(const std::string& scenesFolder);

  MeshFile* body() const { return body_; }
  // The File node holding the body's SkeletonJoints and collision volumes.
  SoNode* volumes() const { return volumes_; }
  // A style's pattern (its rest shape), null when the catalogue has no such style.
  MeshFile* pattern(const std::string& style) const;
  // The point the Mannequin's `height` scales the body about (sim/body/Posing.h): below
  // the root joint, at the lowest joint's height. m.
  const SbVec3f& heightOrigin() const { return heightOrigin_; }
  // The scenes folder's garment catalogue (its styles, sizes and colours), once read.
  const GarmentCatalogue* catalogue() const { return catalogue_.get(); }

 private:
  bool findHeightOrigin();
  std::string readCatalogue(const std::string& scenesFolder);

  SoNode* root_ = nullptr;  // referenced: holds everything below
  MeshFile* body_ = nullptr;
  SoNode* volumes_ = nullptr;
  std::map<std::string, MeshFile*> patterns_;
  SbVec3f heightOrigin_{0, 0, 0};
  std::unique_ptr<GarmentCatalogue> catalogue_;
};

}  // namespace figment::serve
