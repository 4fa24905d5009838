#pragma once
// Files a scene names (a MeshFile's mesh, a ClothEngine's reconstruction script), looked
// up beside the .iv file that names them, then along Coin's and FIGMENT's search paths.

#include <string>
#include <vector>

class SoInput;

namespace figment {

// Where the .iv file being read lives, then the rest of Coin's search list (which
// SoInput starts with that folder while reading a file), as absolute paths: kept at
// read time for later loads, when the working directory may have changed.
std::vector<std::string> sceneSearchDirectories(SoInput* in);

// `name` in the first of `dirs` that has it, else on the model search path
// (io/MeshImport.h, findModelFile); "" when nowhere.
std::string resolveSceneFile(const std::string& name, const std::vector<std::string>& dirs);

}  // namespace figment
