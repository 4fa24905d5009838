#pragma once
// How each draped garment of a scene fits its body (docs/sizes.md): for every ClothingLayer
// drawn from a ClothEngine's positions (through a Coordinate3 before it in its group) whose
// body is a mesh (a MeshFile: a HumanBody, a body read from a file), the garment's rest
// shape and drape, and its fit per region where the body can be measured
// (sim/fit/GarmentFit.h). What figment-view's --fit-map draws and --stats reports.

#include <memory>
#include <string>
#include <vector>

#include "sim/cloth/ClothParameters.h"
#include "sim/collision/MeshCollider.h"
#include "sim/collision/MovingMeshCollider.h"
#include "sim/fit/FitVerdict.h"
#include "sim/fit/GarmentFit.h"

class ClothEngine;
class ClothingLayer;
class SoGroup;
class SoSeparator;

namespace figment {
class MakeHumanLibrary;
}

namespace figment::session {

struct EngineFit {
  ClothEngine* engine = nullptr;  // held through the scene
  std::string name;               // the engine's DEF name
  // The ClothingLayers that draw its drape, each with the group that holds it.
  std::vector<std::pair<SoGroup*, ClothingLayer*>> layers;
  TriangleMesh rest;                         // the garment as cut (restPoints, coordIndex)
  std::vector<Vec3> positions;               // its drape (m)
  TriangleMesh bodyMesh;                     // the skin it collided with
  std::shared_ptr<const MeshCollider> body;  // and its collider
  // A posed HumanBody's skin at rest and posed: its regions are found at rest and the
  // drape carried back to them (sim/fit/PosedSkin.h); null for a standing body.
  std::shared_ptr<const PosedSkin> pose;
  // Its body moving into that pose during the drape (the engine's own collider), for the
  // body as it was at a frame's time (FitMapDrawing); null for a body that stands still.
  std::shared_ptr<const MovingMeshCollider> motion;
  ClothParameters parameters;  // the engine's (material, clearance, gravity)
  FabricLimits limits;         // of its material preset (the woven ones' for none)
  // Per region of the body (empty when the body, or a posed one's rest pose, cannot be
  // measured as a standing human),
  // and their verdicts where the intended fit is known (a CatalogueGarment's size on its
  // own chart body); else empty.
  std::vector<RegionFit> regions;
  std::vector<Verdict> verdicts;
  std::string text;     // the shopper's line with the verdicts; "" without them
  std::string garment;  // the catalogue's name ("dress:M:1f40b3") when the rest shape is a CatalogueGarment's
  FitInput input() const;
};

// The scene's draped garments on mesh bodies, in scene order: drape the scene first.
// `regions` false leaves the regions out (a fit map needs none). With `verdicts`, the
// caller's MakeHumanLibrary, the regions of a catalogue garment are judged against its
// size on its own chart body (that body and drape are made here with it: about 1 s, and
// MakeHuman's data; without the data, no verdicts); null: no verdicts.
std::vector<EngineFit> measureEngineFits(SoSeparator* scene, bool regions, MakeHumanLibrary* verdicts);

}  // namespace figment::session
