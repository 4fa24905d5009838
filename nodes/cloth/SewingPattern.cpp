#include "nodes/cloth/SewingPattern.h"

#include <Inventor/SoInput.h>
#include <Inventor/errors/SoDebugError.h>
#include <Inventor/errors/SoReadError.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "io/PatternFile.h"
#include "nodes/MeshFields.h"
#include "nodes/NodeSource.h"
#include "nodes/SceneFiles.h"
#include "sim/core/ParameterChecks.h"
#include "sim/pattern/PatternCutting.h"
#include "sim/pattern/PatternPlacement.h"

FIGMENT_DERIVED_NODE_SOURCE(SewingPattern, MeshFile)

SewingPattern::SewingPattern() {
  SO_NODE_CONSTRUCTOR(SewingPattern);
  SO_NODE_ADD_FIELD(spacing, (0.02));
  SO_NODE_ADD_FIELD(madeForStature, (0.0));
  SO_NODE_ADD_FIELD(body, (nullptr));
  SO_NODE_ADD_EMPTY_MFIELD(panelPoint);
  SO_NODE_ADD_EMPTY_MFIELD(seams);
}

SewingPattern::~SewingPattern() = default;

bool SewingPattern::isLoadOption(const SoField* field) const {
  return field == &spacing || field == &madeForStature || field == &body || inherited::isLoadOption(field);
}

SbBool SewingPattern::readInstance(SoInput* in, unsigned short flags) {
  // The folders the pattern is looked up in, before MeshFile's read loads it.
  sceneDirectories_ = figment::sceneSearchDirectories(in);
  return inherited::readInstance(in, flags);
}

namespace {

constexpr double kMinSpacing = 0.005, kMaxSpacing = 0.1;  // m

// The pattern's panels cut, placed around the node's body; throws naming the field.
figment::UnsewnGarment cutFor(const SewingPattern& node, const std::vector<std::string>& dirs) {
  const double spacing = node.spacing.getValue();
  if (!(spacing >= kMinSpacing && spacing <= kMaxSpacing))
    throw std::invalid_argument("spacing = " + figment::formatNumber(spacing) + " must be within [" +
                                figment::formatNumber(kMinSpacing) + ", " + figment::formatNumber(kMaxSpacing) + "] m");
  const std::string name = node.fileName.getValue().getString();
  const std::string path = figment::resolveSceneFile(name, dirs);
  if (path.empty()) throw std::runtime_error("fileName \"" + name + "\" not found");
  figment::SewingPattern pattern = figment::readPatternFile(path);
  if (SoNode* body = node.body.getValue()) {
    if (!body->isOfType(MeshFile::getClassTypeId()))
      throw std::invalid_argument(std::string("body is a ") + body->getTypeId().getName().getString() +
                                  ", not a MeshFile");
    const figment::TriangleMesh& surface = static_cast<const MeshFile*>(body)->collisionSurface();
    pattern = figment::placed(pattern, figment::placementOn(surface, node.madeForStature.getValue()));
  }
  return figment::cutPattern(pattern, spacing);
}

}  // namespace

bool SewingPattern::load(SoInput* in) {
  std::string error;
  try {
    if (fileName.getValue().getLength() == 0) {
      clearMesh();
      figment::clearPanelFields(panelPoint, seams);
      return true;
    }
    const figment::UnsewnGarment cut = cutFor(*this, sceneDirectories_);
    setMesh(cut.placed, cut.placed);
    figment::setPanelFields(cut, panelPoint, seams);
    return true;
  } catch (const std::exception& e) {
    error = e.what();
  }
  figment::clearPanelFields(panelPoint, seams);
  return failLoad("SewingPattern", in, error);
}
