#include "BodyChoice.h"

#include <Inventor/SoPath.h>
#include <Inventor/misc/SoChildList.h>
#include <Inventor/nodes/SoFile.h>

#include <filesystem>

#include "nodes/SceneSearch.h"
#include "nodes/body/Mannequin.h"

namespace figment::bench {

SoNode* bodyFor(const std::string& choice, SoNode* root, std::string& error) {
  if (choice == "scene") return nullptr;
  const SoPathList found = findAll(root, Mannequin::getClassTypeId());
  if (found.getLength() != 1) {
    error = "--body " + choice + " needs a scene with one Mannequin";
    return nullptr;
  }
  auto* mannequin = static_cast<Mannequin*>(found[0]->getTail());
  if (choice == "exact") return mannequin->body.getValue();
  // The same mannequin (body, pose, size) with other volumes.
  auto* other = new Mannequin;
  other->copyFieldValues(mannequin);
  auto* file = new SoFile;
  file->ref();
  file->name = std::filesystem::absolute(choice).string().c_str();
  if (file->getChildren()->getLength() == 0) {
    error = "--body " + choice + ": no volumes read from it";
    file->unref();
    other->ref();
    other->unref();
    return nullptr;
  }
  other->addChild(file);
  file->unref();
  return other;
}

}  // namespace figment::bench
