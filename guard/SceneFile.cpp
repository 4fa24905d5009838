#include "guard/SceneFile.h"

#include <Inventor/SoDB.h>
#include <Inventor/nodes/SoSeparator.h>

#include <filesystem>

#include "guard/GuardedInput.h"
#include "guard/NodeFieldRanges.h"
#include "guard/NodeFieldTypes.h"
#include "guard/ReadMessages.h"
#include "guard/SceneExpansion.h"
#include "guard/SceneTextCheck.h"

namespace figment::guard {

namespace {

// What refuses the scene before Coin is given it: "" when Coin may read it.
std::string beforeCoin(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return "no such file";
  if (!std::filesystem::is_regular_file(path, ec)) return "not a file";
  // Coin's reader has no bound on nesting or includes (SceneTextCheck.h).
  return checkSceneText(path);
}

// The read error that carries `refusal`, with its line and file: Coin read on past the include
// it lies in.
std::string refusedLine(const std::string& refusal, const std::vector<std::string>& errors) {
  for (const std::string& error : errors)
    if (error.find(refusal) != std::string::npos) return error;
  return refusal;
}

// What refuses a graph Coin read: "" when nothing does. Before any action: one could traverse
// the graph for hours (SceneExpansion.h), or crash on a node held where another type belongs
// (NodeFieldTypes.h) or an index past Coin's own arrays (NodeFieldRanges.h).
std::string afterCoin(const SoNode* root, const GuardedInput& in, const std::vector<std::string>& errors) {
  if (!in.refusal().empty()) return refusedLine(in.refusal(), errors);
  std::string refused = sceneExpansionProblem(root);
  if (refused.empty()) refused = firstMistypedNodeField(root);
  if (refused.empty()) refused = firstFieldOutOfRange(root);
  return refused;
}

}  // namespace

SoSeparator* readScene(const std::string& path, std::string& error) {
  error = beforeCoin(path);
  if (!error.empty()) return nullptr;
  ReadMessages messages;
  // Holds what DEF names; refuses a field declaration Coin would add to a whole class.
  GuardedInput in;
  if (!in.openFile(path.c_str(), TRUE)) {
    error = "cannot open file";
    return nullptr;
  }
  SoSeparator* root = SoDB::readAll(&in);
  if (root) root->ref();
  in.release();  // what the scene does not hold goes now, before its errors are taken
  const std::vector<std::string> errors = messages.readErrors(path);
  const std::string refused = root ? afterCoin(root, in, errors) : "";
  if (!root || !refused.empty()) {
    if (root) unrefWithoutRecursion(root);
    // The first error is the cause; later ones are Coin unwinding the parse.
    error = !refused.empty() ? refused : errors.empty() ? "not an Inventor scene file" : errors.front();
    return nullptr;
  }
  messages.passOnWarnings();
  return root;
}

}  // namespace figment::guard
