#pragma once
// SewingPattern: a shop's garment as its sewing pattern (GarmentCode's specification
// JSON): panels cut into cloth and placed around the body, ready for a ClothEngine to sew
// and drape.

#include <Inventor/fields/SoMFInt32.h>
#include <Inventor/fields/SoMFVec2f.h>
#include <Inventor/fields/SoSFDouble.h>
#include <Inventor/fields/SoSFNode.h>
#include <Inventor/fields/SoSFString.h>

#include <string>
#include <vector>

#include "nodes/body/MeshFile.h"

/*!
  \class SewingPattern nodes/cloth/SewingPattern.h
  \brief A sewing pattern's panels, cut into cloth and placed around a body, with its seams.

  `fileName` names a pattern in GarmentCode's specification JSON (docs/patterns.md), looked
  up as a MeshFile's file is. The node reads it (io/PatternFile.h), moves its panels onto
  `body` (sim/pattern/PatternPlacement.h: the pattern's feet and axis onto the body's,
  heights scaled by the two statures when `madeForStature` is given), cuts each panel into
  triangles about `spacing` apart (sim/pattern/PatternCutting.h) and offers the result as a
  MeshFile does: `point` and `coordIndex` (the panels as placed, not yet sewn), and two more
  outputs for a ClothEngine: `panelPoint`, each point's panel coordinates (m: the rest shape
  and texture coordinates), and `seams`, pairs of point indices the stitches pull together.
  A ClothEngine given `panelPoints` and `seams` sews the panels shut around its body, then
  drapes the garment; its positions are the sewn garment's (a seam's two points end at one
  place):
  \code
    Switch { whichChild -1
      DEF Skirt SewingPattern { fileName "patterns/pencil/pencil-f-38_specification.json"  body USE Body }
    }
    Coordinate3 {
      point = DEF Drape ClothEngine {
        restPoints = USE Skirt.point  coordIndex = USE Skirt.coordIndex
        panelPoints = USE Skirt.panelPoint  seams = USE Skirt.seams
        body USE Body
      } . positions
    }
    ClothingLayer { coordIndex = USE Skirt.coordIndex }
  \endcode
  A pattern that does not read (one line naming the file and the panel, edge or stitch), a
  body that is not a MeshFile, or a spacing out of range is a read error naming the node
  (a posted error when set from code), and the node is then empty.

  <b>FILE FORMAT/DEFAULTS:</b>
  \code
    SewingPattern {
        fileName ""
        spacing 0.02
        madeForStature 0
        body NULL
    }
  \endcode
*/
class SewingPattern : public MeshFile {
  typedef MeshFile inherited;
  SO_NODE_HEADER(SewingPattern);

 public:
  static void initClass();
  SewingPattern();

  // The cloth's node spacing, m: each edge is sampled about this far apart, and each
  // panel's inside filled with a triangular lattice of it. Default 0.02. Within [0.005, 0.1].
  SoSFDouble spacing;
  // The stature of the body the pattern was made for, m; 0: the same as `body`'s. Default 0.
  SoSFDouble madeForStature;
  // The body the panels are placed around: a MeshFile (its collision surface), or NULL for
  // the pattern's own frame (feet at y = 0, facing +z). Default NULL.
  SoSFNode body;

  // Read-only outputs, set by the node and not written to files.
  // Per point, its panel coordinates (m).
  SoMFVec2f panelPoint;
  // Point index pairs, two per seam: what the stitches pull together.
  SoMFInt32 seams;

 protected:
  ~SewingPattern() override;
  SbBool readInstance(SoInput* in, unsigned short flags) override;
  bool load(SoInput* in) override;
  bool isLoadOption(const SoField* field) const override;

 private:
  std::vector<std::string> sceneDirectories_;  // kept at read time for later loads
};
