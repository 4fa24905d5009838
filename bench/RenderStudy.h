#pragma once
// The rendering study (paper §5): what the hybrid nodes cost over plain depth-buffered
// rendering. Each scene is rendered as written (ClothingLayer, DepthSortedGroup,
// StencilSeparator, with the stencil rule applied per render) and with those nodes
// swapped for IndexedFaceSet, Group and Separator, alternating in rounds: the first
// frame after a switch (a snapshot: nothing cached yet), then frames from a still camera
// (a ClothingLayer re-draws its sorted facets) and from a camera that moves every frame
// (it sorts again every frame).

#include <string>
#include <vector>

namespace figment::bench {

struct RenderStudyOptions {
  std::vector<std::string> scenes = {"scenes/dress.iv", "scenes/hybrid/three-layers.iv"};
  int width = 1024, height = 768;
  int repeat = 40;  // renders per scene, mode and camera
  std::string outDir = "bench-out";
};

// Writes DIR/render.csv and prints the medians and the overhead. Returns the exit code.
int runRenderStudy(const RenderStudyOptions& options);

}  // namespace figment::bench
