#pragma once
// CatalogueGarment: a garment of the catalogue (scenes/catalogue/, io/GarmentCatalogue.h)
// named "style:size[:rrggbb]"; a MeshFile whose mesh is the style cut for that size, or,
// for a pattern style, that size's pattern cut and placed around the size's chart body
// with its seams, for a ClothEngine to sew.

#include <Inventor/fields/SoMFInt32.h>
#include <Inventor/fields/SoMFVec2f.h>
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
  sim/body/MeasuredBody.h) with the style's ease (sim/garment/GarmentStyle.h): a size-M dress
  is one fixed garment whatever body wears it, the same one figment-size drapes. Being a
  MeshFile it offers `point` and `coordIndex` for a ClothEngine's restPoints and coordIndex;
  the file fields are not used and fileName must stay "". Two more outputs: `colour`, the
  name's colour (else the style's first), for a Material's diffuseColor, and `fabric`, the
  style's material preset, for a ClothEngine's material.

  A pattern style ("tee:M", "pencilskirt:38": a shop's own garment, sewn from its size's
  graded pattern, scenes/patterns/) gives what a SewingPattern node gives for that pattern
  placed around the size's chart body (panels cut 2 cm apart, sim/pattern/PatternCutting.h):
  `point` and `coordIndex` are the panels placed but not yet sewn, `panelPoint` each point's
  panel coordinates (m: the rest shape) and `seams` the point pairs the stitches pull
  together, for a ClothEngine's panelPoints and seams; the engine sews the panels shut
  around its body, then drapes. A generated style's panelPoint and seams are empty, which a
  ClothEngine reads as nothing to sew: a scene that connects all four outputs drapes any
  style of the catalogue by its name alone.

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

  Example (scenes/examples/CatalogueGarment.iv; a pattern style:
  scenes/examples/CatalogueGarmentSewn.iv):
  \code
    Switch { whichChild -1  DEF Dress CatalogueGarment { garment "dress:M:1f40b3" } }
    Material { diffuseColor = USE Dress.colour }
    ... ClothEngine { restPoints = USE Dress.point  coordIndex = USE Dress.coordIndex
                      panelPoints = USE Dress.panelPoint  seams = USE Dress.seams
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
  // Read-only outputs for a pattern style (empty for a generated one): per point, its
  // panel coordinates (m); point index pairs, two per seam.
  SoMFVec2f panelPoint;
  SoMFInt32 seams;

 protected:
  ~CatalogueGarment() override;
  SbBool readInstance(SoInput* in, unsigned short flags) override;
  bool load(SoInput* in) override;
  bool isLoadOption(const SoField* field) const override;

 private:
  struct Data;
  std::unique_ptr<Data> data_;  // MakeHuman's targets, read on first use
};
