#pragma once
// CatalogueGarment: a garment of the catalogue (scenes/catalogue/, io/GarmentCatalogue.h)
// named "style:size[:rrggbb]"; a MeshFile whose mesh is the style cut for that size.

#include <Inventor/fields/SoSFColor.h>
#include <Inventor/fields/SoSFString.h>

#include <memory>

#include "nodes/body/MeshFile.h"

/*!
  \class CatalogueGarment nodes/cloth/CatalogueGarment.h
  \brief A graded garment named by the catalogue: its rest shape, colour and fabric.

  `garment` names one garment of the catalogue, "style:size[:rrggbb]" (docs/sizes.md):
  "dress:M" is the strap dress in the women's M, "tshirt:38" the T-shirt in the women's 38,
  "pencil:S:222222" the pencil skirt in S, black. The mesh is the style cut around the size's
  chart body (MakeHuman's body made to the chart's stature, bust, waist and hip girth,
  sim/body/BodyFit.h) with the style's ease (sim/garment/GarmentStyle.h): a size-M dress
  is one fixed garment whatever body wears it, the same one figment-size drapes. Being a
  MeshFile it offers `point` and `coordIndex` for a ClothEngine's restPoints and coordIndex;
  the file fields are not used and fileName must stay "". Two more outputs: `colour`, the
  name's colour (else the style's first), for a Material's diffuseColor, and `fabric`, the
  style's material preset, for a ClothEngine's material.

  A bad name, a catalogue that does not read or MakeHuman's data missing is a read error
  naming the node, the field, the value and the accepted names (a posted error when set
  from code), and the node is then empty.

  <b>FILE FORMAT/DEFAULTS:</b>
  \code
    CatalogueGarment {
        garment ""
        catalogue ""
    }
  \endcode

  Example (scenes/examples/CatalogueGarment.iv):
  \code
    Switch { whichChild -1  DEF Dress CatalogueGarment { garment "dress:M:1f40b3" } }
    Material { diffuseColor = USE Dress.colour }
    ... ClothEngine { restPoints = USE Dress.point  coordIndex = USE Dress.coordIndex
                      material = USE Dress.fabric ... }
  \endcode
*/
class CatalogueGarment : public MeshFile {
  typedef MeshFile inherited;
  SO_NODE_HEADER(CatalogueGarment);

 public:
  static void initClass();
  CatalogueGarment();

  // "style:size[:rrggbb]": a style of the catalogue, a size by the chart's letter code (in
  // the sex the style's file lists first) or number, and an optional colour. Default "" (no
  // mesh).
  SoSFString garment;
  // The catalogue's index file, looked up as a MeshFile's fileName is; "" is the one shipped
  // with the sources (scenes/catalogue/index.txt). Default "".
  SoSFString catalogue;

  // Read-only outputs, set by the node and not written to files: the garment's colour
  // (sRGB, 0..1) and its fabric (a material preset: "jersey", "cotton").
  SoSFColor colour;
  SoSFString fabric;

 protected:
  ~CatalogueGarment() override;
  SbBool readInstance(SoInput* in, unsigned short flags) override;
  bool load(SoInput* in) override;
  bool isLoadOption(const SoField* field) const override;

 private:
  struct Data;
  std::unique_ptr<Data> data_;  // MakeHuman's targets, read on first use
};
