#include "session/FitMapDrawing.h"

#include <Inventor/nodes/SoGroup.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>
#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoMaterialBinding.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoShapeHints.h>

#include "nodes/render/ClothingLayer.h"

namespace figment::session {

std::vector<int> fitMapBands(const EngineFit& fit, FitMapKind kind) {
  return figment::fitMapBands(fit.input(), kind, fit.limits);
}

std::vector<int> fitMapBands(const EngineFit& fit, const std::vector<SbVec3f>& positions, double time,
                             FitMapKind kind) {
  if (positions.size() != fit.rest.vertices.size()) return fitMapBands(fit, kind);
  std::vector<Vec3> state;
  state.reserve(positions.size());
  for (const SbVec3f& p : positions) state.emplace_back(p[0], p[1], p[2]);
  FitInput input = fit.input();
  input.positions = &state;
  if (!fit.motion || time >= fit.motion->duration()) return figment::fitMapBands(input, kind, fit.limits);
  // The engine's moving body, at the frame's keyframe and then back at its end (as drawn,
  // and as the drape left it).
  fit.motion->advanceTo(time);
  input.body = &fit.motion->current();
  std::vector<int> bands = figment::fitMapBands(input, kind, fit.limits);
  fit.motion->advanceTo(fit.motion->duration());
  return bands;
}

void colourFitMap(SoIndexedFaceSet* faces, const std::vector<int>& bands) {
  const int count = faces->coordIndex.getNum();
  faces->materialIndex.setNum(count);
  int32_t* index = faces->materialIndex.startEditing();
  for (int i = 0; i < count; ++i) {
    const int corner = faces->coordIndex[i];
    index[i] = corner < 0 || corner >= int(bands.size()) ? -1 : bands[corner];
  }
  faces->materialIndex.finishEditing();
}

std::vector<SoIndexedFaceSet*> drawFitMap(const EngineFit& fit, const std::vector<int>& bands) {
  std::vector<SoIndexedFaceSet*> drawn;
  for (const auto& [group, layer] : fit.layers) {
    auto* map = new SoSeparator;
    auto* material = new SoMaterial;
    for (int band = 0; band < kFitMapBands; ++band) {
      const Vec3 c = fitMapColour(band);
      material->diffuseColor.set1Value(band, float(c.x()), float(c.y()), float(c.z()));
    }
    auto* binding = new SoMaterialBinding;
    binding->value = SoMaterialBinding::PER_VERTEX_INDEXED;
    // Cloth is seen from both sides, as the shipped scenes' ShapeHints say.
    auto* hints = new SoShapeHints;
    hints->vertexOrdering = SoShapeHints::COUNTERCLOCKWISE;
    hints->shapeType = SoShapeHints::UNKNOWN_SHAPE_TYPE;
    hints->creaseAngle = 1.0f;
    auto* faces = new SoIndexedFaceSet;
    const int count = layer->coordIndex.getNum();
    faces->coordIndex.setValues(0, count, layer->coordIndex.getValues(0));
    colourFitMap(faces, bands);
    map->addChild(material);
    map->addChild(binding);
    map->addChild(hints);
    map->addChild(faces);
    group->replaceChild(layer, map);
    drawn.push_back(faces);
  }
  return drawn;
}

}  // namespace figment::session
