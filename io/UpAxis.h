#pragma once
// A mesh file's up axis and the rotation that stands it in the scene frame (y up), shared
// by MeshFile's `upAxis` field, importMesh and the tools' --up-axis option, so that all
// three bring a file into the same frame.

#include <optional>
#include <string>

#include "sim/core/TriangleMesh.h"

namespace figment {

enum class UpAxis { X, Y, Z, NegX, NegY, NegZ };

// The proper rotation (determinant +1: windings and handedness survive) that takes the
// file's `up` direction onto +y.
Vec3 toYUp(const Vec3& p, UpAxis up);

// The name MeshFile's upAxis field and the tools use: X, Y, Z, NEG_X, NEG_Y, NEG_Z.
std::string upAxisName(UpAxis up);

// The axis named `name` (as upAxisName writes it, any case); nullopt for any other text.
std::optional<UpAxis> parseUpAxis(const std::string& name);

// The file axis that `up` ends on +y, where the file's vertices were brought in with
// `applied`: a body found standing along `up` after importing with upAxis = applied
// stands along the returned axis in the file. nullopt unless `up` is an axis direction.
std::optional<UpAxis> fileUpAxis(const Vec3& up, UpAxis applied);

}  // namespace figment
