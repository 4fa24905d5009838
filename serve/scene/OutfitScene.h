#pragma once
// A render request's scene, built in code from FIGMENT's nodes (never from text a
// request holds): the lights of its preset; the body, its skin; and each garment of the
// outfit, innermost first, draped by a ClothEngine on the body and on the draped surfaces
// of the garments under it, as scenes/outfit-layers.iv drapes its two.
//
// The made body (the default) is MakeHuman's HumanBody made to the measurements and posed,
// and each garment is its style's graded garment of the chart's size (what GET /api/fit
// drapes for that size), draped with the size advice's settings. The Mannequin
// (body=mannequin) is the paper's scanned body sized by the measurements
// (ShopperChoices::bodyFactors) and posed, in the paper's patterns as cut, with the same
// nodes and settings as the shipped scenes, so it drapes as a scene file would.

#include <functional>
#include <optional>
#include <stdexcept>
#include <vector>

#include "serve/request/RenderRequest.h"
#include "sim/cloth/ClothParameters.h"
#include "sim/core/TriangleMesh.h"
#include "sim/drape/GarmentDrape.h"
#include "sim/fit/SizeFitter.h"
#include "sim/pattern/UnsewnGarment.h"

class ClothEngine;
class HumanBody;
class MeshFile;
class SoCoordinate3;
class SoMaterial;
class SoSeparator;

namespace figment::serve {

class Wardrobe;

class OutfitScene {
 public:
  // Levels of display mesh each garment's ClothingLayer draws (its displaySubdivision), as
  // the shipped scenes' do: one, each triangle as four on a smooth surface. A fit map is
  // drawn on the simulation's faces (a ClothingLayer draws one material).
  static constexpr int kDisplaySubdivision = 1;

  // A style's garment graded to a size of the chart, for a measured body (a sewn style's:
  // its panels placed round the size's chart body, and their flat shapes); throws when it
  // cannot be made.
  using GradedGarment = std::function<const SizeFitter::Graded&(const OutfitItem& item, Sex sex)>;
  // A sewn style's size cut and placed around the request's made body, unsewn, for a
  // ClothEngine to sew (a garment that is not drawn from its size drape: an outer layer).
  using SewnCut = std::function<UnsewnGarment(const RenderRequest& request, const OutfitItem& item)>;
  // The one drape of a made body × garment size (serve/workers/FitWorker.h's sizeDrape): the
  // drape the size advice judges. A made body at rest draws its innermost garment from it
  // rather than draping it again.
  using SizeDrape = std::function<GarmentDrape(const RenderRequest& request, const OutfitItem& item)>;
  // What a made body's garments come from; both are asked only for a made body.
  struct Made {
    GradedGarment graded;
    SewnCut sewnCut;
    SizeDrape sizeDrape;  // null: every garment drapes in the scene
    // The made body at rest, kept by the worker between scenes (made by makeBody); null:
    // made for this scene.
    std::function<HumanBody*(const RenderRequest& request)> restBody;
  };
  // The made body of `request` (its measurements, sex and pose), referenced once for the
  // caller. Throws BodyNotMade.
  static HumanBody* makeBody(const RenderRequest& request);

  // A measured body MakeHuman did not make (measurements out of its reach, or its data
  // missing): the worker asks why (FitWorker::unreachable).
  class BodyNotMade : public std::runtime_error {
   public:
    using std::runtime_error::runtime_error;
  };

  // A garment drawn as its fit map (RenderRequest::fitMap): an IndexedFaceSet coloured per
  // vertex by `material`, painted once the drape is done. Nodes of the built scene.
  struct FitMapGarment {
    TriangleMesh rest;              // the garment as cut
    std::optional<RestShape> flat;  // a sewn garment's rest shape: its flat panels
    SoCoordinate3* coordinates;     // the drape's positions
    SoMaterial* material;           // one colour per vertex
    std::string fabric;             // a material preset (sim/cloth/MaterialPresets.h): its limits
    std::string kind;               // stretch, ease or pressure (RenderRequest::fitMap)
    const MeshFile* skin;           // for ease and pressure: the measured body; else null
    ClothParameters parameters;     // for ease and pressure: the drape's (clearance, material)
  };

  // The scene's root, not referenced (SceneSession::adopt takes it). `made` is asked only
  // for a made body. With a fit map, its garments go to `fitMaps`; the reports of the size
  // drapes drawn (not draped here) to `drawn`. Throws BodyNotMade.
  static SoSeparator* build(const RenderRequest& request, const Wardrobe& wardrobe, const Made& made = {},
                            std::vector<FitMapGarment>* fitMaps = nullptr, std::vector<DrapeReport>* drawn = nullptr);
  // Colours each garment by the bands of its fit map (sim/fit/FitMap.h) after the drape.
  static void paintFitMaps(const std::vector<FitMapGarment>& fitMaps);
};

}  // namespace figment::serve
