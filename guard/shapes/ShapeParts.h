#pragma once
// How many vertices, parts and faces an Inventor vertex shape draws: what a material, normal or
// texture coordinate bound PER_VERTEX, PER_PART or PER_FACE is taken for, one after another,
// as Coin counts them (a line set's parts are its segments and its faces its polylines; a
// triangle strip set's parts its strips and its faces its triangles; a quad mesh's parts its
// rows of quads).

#include <cstdint>

class SoIndexedShape;
class SoNonIndexedShape;

namespace figment::guard::shapes {

struct ShapeParts {
  std::int64_t vertices = 0;
  std::int64_t parts = 0;
  std::int64_t faces = 0;
};

ShapeParts indexedShapeParts(const SoIndexedShape& shape);

// `shape` drawn from `coordinates` points (its counts within them: countedShapeProblem).
ShapeParts countedShapeParts(const SoNonIndexedShape& shape, std::int64_t coordinates);

}  // namespace figment::guard::shapes
