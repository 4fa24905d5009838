#pragma once
// figment-view --fit-map: a draped garment drawn in its fit map's colours (sim/fit/FitMap.h:
// blue at rest to red at the fabric's limit, eight bands), as figment-size's fit-map scenes
// draw it (io/FitMapScene.h): an IndexedFaceSet coloured per vertex by band.

#include <Inventor/SbVec3f.h>

#include "session/EngineFit.h"
#include "sim/fit/FitMap.h"

class SoIndexedFaceSet;

namespace figment::session {

// Each vertex's band (0 to kFitMapBands - 1) of `kind` on `fit`'s drape.
std::vector<int> fitMapBands(const EngineFit& fit, FitMapKind kind);
// The same on another state of its drape (a frame of figment-view --frames: `positions`,
// one per rest point, at `time` s simulated), against the body as it was then (a posed
// HumanBody moving into its pose: its keyframe at or before `time`).
std::vector<int> fitMapBands(const EngineFit& fit, const std::vector<SbVec3f>& positions, double time, FitMapKind kind);

// Replaces each ClothingLayer of `fit` in its group by a separator drawing the same faces
// (the Coordinate3 before it holds the drape) coloured by `bands`, seen from both sides.
// The layers are gone afterwards: `fit.layers` must not be used again. Returns the face
// sets drawn (one per layer), for colourFitMap.
std::vector<SoIndexedFaceSet*> drawFitMap(const EngineFit& fit, const std::vector<int>& bands);

// Colours a face set drawFitMap made by other bands (of the drape's state it now shows).
void colourFitMap(SoIndexedFaceSet* faces, const std::vector<int>& bands);

}  // namespace figment::session
