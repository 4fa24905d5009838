#pragma once
// figment-view --list-nodes: FIGMENT's node and engine types and their fields, read from
// Coin's own field data (SoFieldData), so the list is always what a scene may write.

#include <Inventor/SoType.h>

#include <functional>
#include <string>
#include <vector>

namespace figment::viewer {

// The node and engine types that `registerTypes` adds to Coin's type system (those
// derived from SoNode or SoEngine that were unknown before it ran), by name. Coin must
// be initialised first (SoDB::init).
std::vector<SoType> typesAddedBy(const std::function<void()>& registerTypes);

// For each type, a heading "Name (node|engine, derived from Parent)" and one line per
// field: its name, field type and default value as an .iv file writes it (an enum's
// choices after it in braces); an engine's outputs follow as "output NAME TYPE". An
// abstract type says so and lists nothing.
std::string describeTypes(const std::vector<SoType>& types);

}  // namespace figment::viewer
