#include "guard/SceneExpansion.h"

#include <Inventor/fields/SoMFNode.h>
#include <Inventor/fields/SoSFNode.h>
#include <Inventor/nodes/SoArray.h>
#include <Inventor/nodes/SoGroup.h>
#include <Inventor/nodes/SoMultipleCopy.h>
#include <Inventor/nodes/SoNode.h>

#include <algorithm>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "guard/NodeLinks.h"

namespace figment::guard {

namespace {

constexpr std::uint64_t kPastVisits = kMaxNodeVisits + 1;
constexpr int kPastDepth = kMaxGraphDepth + 1;

std::uint64_t cappedSum(std::uint64_t a, std::uint64_t b) {
  return std::min(a + b, kPastVisits);
}
std::uint64_t cappedProduct(std::uint64_t a, std::uint64_t b) {
  return a != 0 && b > kPastVisits / a ? kPastVisits : std::min(a * b, kPastVisits);
}

// How many times a node's children are traversed for each time it is.
std::uint64_t copies(const SoNode& node) {
  if (node.isOfType(SoArray::getClassTypeId())) {
    const auto& array = static_cast<const SoArray&>(node);
    std::uint64_t n = 1;  // a count below 1 draws nothing
    for (const short count :
         {array.numElements1.getValue(), array.numElements2.getValue(), array.numElements3.getValue()})
      n = cappedProduct(n, static_cast<std::uint64_t>(std::max<short>(count, 0)));
    return n;
  }
  if (node.isOfType(SoMultipleCopy::getClassTypeId()))
    return static_cast<std::uint64_t>(static_cast<const SoMultipleCopy&>(node).matrix.getNum());
  return 1;
}

class Expander {
 public:
  SceneExpansion run(const SoNode* root) {
    const Subgraph whole = expand(root, 1);
    return {whole.visits, whole.depth, culprit_};
  }

 private:
  struct Subgraph {
    std::uint64_t visits = 0;
    int depth = 0;
    bool inProgress = false;  // on the path being expanded: a cycle if met again
  };

  // The subgraph under `node`, which lies `level` nodes down from the root. A node is
  // expanded once (shared nodes are looked up); past a bound nothing further is expanded, so
  // the recursion stays within kPastDepth frames.
  Subgraph expand(const SoNode* node, int level) {
    if (level > kMaxGraphDepth) return past(node);
    const auto known = subgraphs_.find(node);
    if (known != subgraphs_.end()) return known->second.inProgress ? past(node) : known->second;
    subgraphs_[node].inProgress = true;
    Subgraph sum{1, 1, false};
    const std::vector<SoNode*> links = linkedNodes(*node);
    const std::uint64_t n = copies(*node);
    std::uint64_t linkedVisits = 0;
    for (std::size_t i = 0; i < links.size() && sum.visits < kPastVisits && sum.depth < kPastDepth; ++i) {
      const Subgraph linked = expand(links[i], level + 1);
      linkedVisits = cappedSum(linkedVisits, linked.visits);
      sum.depth = std::max(sum.depth, std::min(linked.depth + 1, kPastDepth));
      sum.visits = cappedSum(1, cappedProduct(n, linkedVisits));
      // Siblings can pass the bound together: the one that took the sum past it is named,
      // or the Array or MultipleCopy that multiplied them past it.
      if ((sum.visits >= kPastVisits || sum.depth >= kPastDepth) && !culprit_) culprit_ = n > 1 ? node : links[i];
    }
    // Coin loops over an Array's or MultipleCopy's copies whether it has children or not: an
    // empty Array of 30000 x 15000 x 3000 took 19 s to bound (found by fuzz_scene).
    if (n > 1) sum.visits = std::max(sum.visits, cappedSum(1, n));
    if ((sum.visits >= kPastVisits || sum.depth >= kPastDepth) && !culprit_) culprit_ = node;
    subgraphs_[node] = sum;
    return sum;
  }

  Subgraph past(const SoNode* node) {
    if (!culprit_) culprit_ = node;
    return {kPastVisits, kPastDepth, false};
  }

  std::unordered_map<const SoNode*, Subgraph> subgraphs_;
  const SoNode* culprit_ = nullptr;
};

}  // namespace

SceneExpansion expandScene(const SoNode* root) {
  return Expander().run(root);
}

void unrefWithoutRecursion(SoNode* root) {
  std::vector<SoNode*> nodes;  // each referenced here, so none goes while the links are cut
  std::unordered_set<SoNode*> seen;
  for (std::vector<SoNode*> next{root}; !next.empty();) {
    SoNode* node = next.back();
    next.pop_back();
    if (!seen.insert(node).second) continue;
    node->ref();
    nodes.push_back(node);
    for (SoNode* linked : linkedNodes(*node)) next.push_back(linked);
  }
  for (SoNode* node : nodes) {
    if (node->isOfType(SoGroup::getClassTypeId())) static_cast<SoGroup*>(node)->removeAllChildren();
    for (SoField* field : nodeFields(*node)) {
      field->disconnect();
      if (field->isOfType(SoSFNode::getClassTypeId()))
        static_cast<SoSFNode*>(field)->setValue(nullptr);
      else
        static_cast<SoMFNode*>(field)->deleteValues(0);
    }
  }
  root->unref();
  for (SoNode* node : nodes) node->unref();  // childless now: each goes on its own
}

std::string sceneExpansionProblem(const SoNode* root) {
  const SceneExpansion expansion = expandScene(root);
  const std::string where = expansion.culprit ? " (passed at " + describeNode(*expansion.culprit) + ")" : "";
  if (expansion.depth > kMaxGraphDepth)
    return "the scene graph is more than " + std::to_string(kMaxGraphDepth) + " nodes deep, counting through each USE" +
           where;
  if (expansion.visits > kMaxNodeVisits)
    return "the scene would draw more than " + std::to_string(kMaxNodeVisits) +
           " nodes, counting a USEd node once for each use and an Array's or MultipleCopy's children once "
           "for each copy" +
           where;
  return "";
}

}  // namespace figment::guard
