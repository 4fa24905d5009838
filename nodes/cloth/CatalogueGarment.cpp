#include "nodes/cloth/CatalogueGarment.h"

#include <Inventor/SoInput.h>
#include <Inventor/errors/SoDebugError.h>
#include <Inventor/errors/SoReadError.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "io/GarmentCatalogue.h"
#include "io/MakeHumanLibrary.h"
#include "io/PatternFile.h"
#include "nodes/MeshFields.h"
#include "nodes/NodeSource.h"
#include "nodes/SceneFiles.h"
#include "sim/pattern/PatternCutting.h"
#include "sim/pattern/PatternPlacement.h"

struct CatalogueGarment::Data {
  std::vector<std::string> sceneDirectories;  // kept at read time for later loads
  figment::MakeHumanLibrary human;            // this node's: the targets its chart bodies blend, read once
};

FIGMENT_DERIVED_NODE_SOURCE(CatalogueGarment, MeshFile)

CatalogueGarment::CatalogueGarment() : data_(std::make_unique<Data>()) {
  SO_NODE_CONSTRUCTOR(CatalogueGarment);
  SO_NODE_ADD_FIELD(garment, (""));
  SO_NODE_ADD_FIELD(catalogue, (""));
  SO_NODE_ADD_FIELD(colour, (0.8f, 0.8f, 0.8f));
  SO_NODE_ADD_FIELD(fabric, (""));
  SO_NODE_ADD_EMPTY_MFIELD(panelPoint);
  SO_NODE_ADD_EMPTY_MFIELD(seams);
}

CatalogueGarment::~CatalogueGarment() = default;

bool CatalogueGarment::isLoadOption(const SoField* field) const {
  return field == &garment || field == &catalogue || inherited::isLoadOption(field);
}

SbBool CatalogueGarment::readInstance(SoInput* in, unsigned short flags) {
  // The folders the catalogue is looked up in, before MeshFile's read loads the mesh.
  data_->sceneDirectories = figment::sceneSearchDirectories(in);
  return inherited::readInstance(in, flags);
}

namespace {

// The catalogue `node` names, read; throws naming the field.
figment::GarmentCatalogue readCatalogue(const CatalogueGarment& node, const std::vector<std::string>& dirs) {
  const std::string name = node.catalogue.getValue().getString();
  if (name.empty()) return figment::GarmentCatalogue(figment::defaultCataloguePath());
  const std::string path = figment::resolveSceneFile(name, dirs);
  if (path.empty()) throw std::invalid_argument("catalogue \"" + name + "\": no such file");
  try {
    return figment::GarmentCatalogue(path);
  } catch (const std::exception& error) {
    throw std::invalid_argument("catalogue \"" + name + "\": " + error.what());
  }
}

// A pattern style's cloth spacing, m: as figment-size and figment-sew cut (SewingPattern's
// default), so the scene drapes the garment the size advice measured.
constexpr double kPatternSpacing = 0.02;

SbColor colourOf(const std::string& hex) {
  const unsigned long rgb = std::stoul(hex, nullptr, 16);
  return SbColor(float((rgb >> 16) & 0xff) / 255.0f, float((rgb >> 8) & 0xff) / 255.0f, float(rgb & 0xff) / 255.0f);
}

}  // namespace

bool CatalogueGarment::load(SoInput* in) {
  std::string error;
  try {
    if (fileName.getValue().getLength() != 0)
      throw std::invalid_argument("fileName \"" + std::string(fileName.getValue().getString()) +
                                  "\": a CatalogueGarment makes its mesh; leave fileName empty");
    const std::string name = garment.getValue().getString();
    figment::clearPanelFields(panelPoint, seams);
    if (name.empty()) {
      clearMesh();
      return true;
    }
    const figment::GarmentCatalogue shop = readCatalogue(*this, data_->sceneDirectories);
    figment::CatalogueItem item;
    try {
      item = shop.resolve(name);
    } catch (const std::invalid_argument& bad) {
      throw std::invalid_argument(std::string("garment ") + bad.what());
    }
    const figment::TriangleMesh body = data_->human.measuredBody(shop.chart().sizes(item.sex)[item.size]).body;
    if (item.sewn()) {
      const figment::SewingPattern pattern = figment::readPatternFile(item.patternFile);
      const figment::UnsewnGarment cut = figment::cutPattern(
          figment::placed(pattern, figment::placementOn(body, item.madeForStature)), kPatternSpacing);
      setMesh(cut.placed, cut.placed);
      figment::setPanelFields(cut, panelPoint, seams);
    } else {
      const figment::TriangleMesh cut = figment::cutGarment(*item.style, body);
      setMesh(cut, cut);
    }
    colour.setValue(colourOf(item.colour));
    fabric.setValue(item.fabric.c_str());
    // Outputs, not settings: left out of written files.
    colour.setDefault(TRUE);
    fabric.setDefault(TRUE);
    return true;
  } catch (const std::exception& e) {
    error = e.what();
  }
  figment::clearPanelFields(panelPoint, seams);
  return failLoad("CatalogueGarment", in, error);
}
