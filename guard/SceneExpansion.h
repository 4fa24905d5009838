#pragma once
// A look at a read scene graph before any action traverses it. An action visits a shared
// (USEd) node once for each path to it, and an Array's or MultipleCopy's children once per
// copy, so a few lines of text can make a graph no traversal finishes: 40 groups each using
// the one before twice draw 2^40 cubes, `Array { numElements1 30000 numElements2 30000
// numElements3 30000 }` 2.7e13, and 100,000 groups each using the one before are 100,000
// levels deep (Coin recurses once per level). The text check (SceneTextCheck.h) cannot see
// these: the text nests one level deep.

#include <cstdint>
#include <string>

class SoNode;

namespace figment::guard {

// Node visits of one traversal of the whole graph (every child of every group, as a search
// for every node does, and every node a field holds: NodeLinks.h), each shared node and copy
// counted. Shipped scenes make at most 107.
// Small, as a search makes a path for each visit of a node it finds, and each path audits
// every node along it: the cost grows with the square of the paths (65,520 took 4.9 s).
inline constexpr std::uint64_t kMaxNodeVisits = 20'000;
// Nodes along one path, root to leaf, through children and node fields: Coin recurses once
// per node, traversing and destroying. Twice the text's nesting
// bound (kMaxNestingDepth), as the graph has levels the text does not (the root readAll
// makes, the contents of a File or an Inline), and far from Coin's stack running out.
inline constexpr int kMaxGraphDepth = 512;

struct SceneExpansion {
  std::uint64_t visits = 0;  // kMaxNodeVisits + 1 once past the bound
  int depth = 0;             // kMaxGraphDepth + 1 once past the bound
  // The innermost node whose subgraph passed a bound, or that took its siblings' sum past it.
  const SoNode* culprit = nullptr;
};

// Counts what a traversal of `root` would visit, stopping where a bound is passed.
SceneExpansion expandScene(const SoNode* root);

// "" when a traversal of `root` stays within both bounds; else one line saying which bound
// was passed and where: "the scene would draw more than 20000 nodes, ... (passed at Array
// 'Grid')".
std::string sceneExpansionProblem(const SoNode* root);

// Releases the caller's reference to `root` as unref() would, taking the graph apart first so
// that destroying it does not recurse once per level: Coin's destructors unref children and
// the nodes fields hold recursively, and 100,000 groups each using the one before overflowed
// the stack (SIGSEGV) when the refused scene was let go, as did 19,500 VRMLTexts each holding
// the one before as its fontStyle.
void unrefWithoutRecursion(SoNode* root);

}  // namespace figment::guard
