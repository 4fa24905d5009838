#pragma once
// The one-line messages of the shape data check (guard/FaceIndexCheck.h): which node, which
// field, which entry, and what it indexes past.

#include <cstdint>
#include <string>

class SoNode;
class SoMFInt32;

namespace figment::guard::shapes {

// "IndexedFaceSet 'Faces'", or the type alone for a node without a name.
std::string nodeLabel(const SoNode& node);

// "1 material", "3 materials"; "2 vertices" with `plural` given.
std::string counted(std::int64_t count, const std::string& noun, const std::string& plural = "");

// Whether Coin takes `index` as given: Coin reads an index field whose first entry is
// negative, or that is empty, as absent.
bool given(const SoMFInt32& index);

// What an index field indexes: `size` entries, each a `noun`, as `has` says ("the
// coordinates have 4 points", "the Material has 1 material").
struct Indexed {
  int size;
  std::string noun;
  std::string has;
};

// "" when every entry of `index` is an entry of `indexed` or the -1 that ends a face, else
// "<node>: <field>[i] = v is not a <noun>: <has>", or "... is neither a <noun> nor the -1 that
// ends a face" for an entry below -1.
std::string indexProblem(const SoNode& node, const std::string& field, const SoMFInt32& index, const Indexed& indexed);

// "" when `index` has at least `needed` entries, one for each of what it runs along, else
// "<node>: <field> has 2 entries for <along>" (along: "the 8 entries of coordIndex",
// "3 faces"): Coin reads an index along the faces or vertices without looking at its length.
std::string shortIndexProblem(const SoNode& node, const std::string& field, const SoMFInt32& index, int needed,
                              const std::string& along);

// The faces of `coordIndex`: its runs of vertices, each ended by a negative entry or the end.
int faceCount(const SoMFInt32& coordIndex);

}  // namespace figment::guard::shapes
