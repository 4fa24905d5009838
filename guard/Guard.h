#pragma once
// FIGMENT's guard: what a Coin program calls so that no scene file, however hostile, crashes or
// hangs it. It needs Coin and nothing else (libfigment_guard; find_package(Figment) gives
// figment::guard), and its two calls are the whole of it, in this order:
//
//   SoSeparator* root = figment::guard::readScene(path, error);   // SceneFile.h
//   ... evaluate what feeds the shapes (drape: read a ClothEngine's positions) ...
//   std::string bad = figment::guard::checkShapes(root);           // FaceIndexCheck.h
//   ... only then bound, stage or render root ...
//
// Each returns one line when it refuses ("line 4: CapsuleVolume: fields [ SFFloat r1e308 ]
// declares a field CapsuleVolume does not have (in volumes.iv)", "ClothingLayer 'Shirt':
// coordIndex[3] = 2147483647 is not a vertex: the coordinates have 4 points"); a refused scene
// is released, never half read. figment::session::SceneSession makes both calls, so figment-view,
// figment-bench and the fuzz targets get the same checks. A C program, or a pivy (Python) one
// through ctypes, makes them through GuardC.h. docs/bad-input.md lists what each refuses.

#include "guard/FaceIndexCheck.h"
#include "guard/SceneFile.h"
