#include "viewer/SceneFile.h"

#include "viewer/CoinMessages.h"
#include "viewer/GuardedInput.h"
#include "viewer/NodeFieldRanges.h"
#include "viewer/NodeFieldTypes.h"
#include "viewer/SceneExpansion.h"
#include "viewer/SceneTextCheck.h"

#include <Inventor/SoDB.h>
#include <Inventor/nodes/SoSeparator.h>

#include <filesystem>

namespace figment::viewer {

namespace {

// The read error that carries `refusal`, with its line and file: Coin read on past the include
// it lies in.
std::string refusedLine(const std::string& refusal, const std::vector<std::string>& errors) {
  for (const std::string& error : errors)
    if (error.find(refusal) != std::string::npos) return error;
  return refusal;
}

}  // namespace

SoSeparator* readSceneFile(const std::string& path, std::string& error) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    error = "no such file";
    return nullptr;
  }
  if (!std::filesystem::is_regular_file(path, ec)) {
    error = "not a file";
    return nullptr;
  }
  // Before Coin: its reader has no bound on nesting or includes (SceneTextCheck.h).
  error = checkSceneText(path);
  if (!error.empty()) return nullptr;
  CoinMessages::takeReadErrors(path);  // only this file's errors count
  // Holds what DEF names; refuses a field declaration Coin would add to a whole class.
  GuardedInput in;
  if (!in.openFile(path.c_str(), TRUE)) {
    error = "cannot open file";
    return nullptr;
  }
  CoinMessages::holdWarnings();
  SoSeparator* root = SoDB::readAll(&in);
  if (root) root->ref();
  in.release();  // what the scene does not hold goes now, before its errors are taken
  // Before any action: one could traverse the graph for hours (SceneExpansion.h), or crash
  // on a node held where another type belongs (NodeFieldTypes.h) or an index past Coin's
  // own arrays (NodeFieldRanges.h).
  std::string refused;
  if (root && !in.refusal().empty()) refused = refusedLine(in.refusal(), CoinMessages::takeReadErrors(path));
  if (root && refused.empty()) refused = sceneExpansionProblem(root);
  if (root && refused.empty()) refused = firstMistypedNodeField(root);
  if (root && refused.empty()) refused = firstFieldOutOfRange(root);
  if (!refused.empty()) {
    unrefWithoutRecursion(root);
    root = nullptr;
  }
  CoinMessages::releaseWarnings(root != nullptr);
  const std::vector<std::string> errors = CoinMessages::takeReadErrors(path);
  if (!root) {
    // The first error is the cause; later ones are Coin unwinding the parse.
    error = !refused.empty() ? refused : errors.empty() ? "not an Inventor scene file" : errors.front();
    return nullptr;
  }
  return root;
}

}  // namespace figment::viewer
