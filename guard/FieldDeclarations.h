#pragma once
// A node's `fields [ ... ]` declaration, checked against the fields its class has, as Coin
// reads it.
//
// A file written by Coin declares the fields of every node that is not built into Coin
// (FIGMENT's nodes among them): `CapsuleVolume { fields [ SFString part, SFFloat r1 ] ... }`.
// Coin's reader adds a declared field the node lacks to its class's field list, which every
// node of the class shares, at the offset of the new field from this one node: every other
// node of the class then has a "field" at a wild address. `SFFloat r1e308` in an included
// CapsuleVolume crashed figment-view (SIGSEGV when the graph was walked), as `Cube { fields
// [ SFFloat wobble ] }` does, and the class stays broken for the rest of the process
// (docs/coin-bugs.md). A declared type other than the field's is taken without a word (the
// value is then read as the field's own type): the file is not what it says, and is refused
// as well.

#include <Inventor/SoType.h>

#include <map>
#include <string>
#include <vector>

class SbName;

namespace figment::guard {

class FieldDeclarations {
 public:
  // Takes each name Coin's reader reads, in order. Returns "" or, for the field name of a
  // declaration that does not match the node's class, one line naming node and field:
  // "CapsuleVolume 'Head': fields [ SFFloat r1e308 ] declares a field CapsuleVolume does not
  // have", "... fields [ SFInt32 r1 ] declares r1 an SFInt32, but it is an SFFloat".
  std::string seeName(const SbName& name);
  // Takes each character Coin's reader reads on its own (braces, brackets, commas).
  void seeChar(char c);

 private:
  struct Field {
    std::string name;
    SoType type;
  };
  // What a class's nodes share: their fields, when they share one field list (every class
  // but Coin's unknown nodes and scripts, whose nodes each have their own).
  struct ClassFields {
    bool shared = false;
    std::vector<Field> fields;
  };
  const ClassFields& classFields(SoType type);
  bool startsDeclaration(const std::string& word);
  std::string check(const std::string& field) const;

  enum class Stage { kOutside, kType, kName };
  Stage stage_ = Stage::kOutside;
  std::vector<std::string> names_;  // the last three names read: DEF, its name, the class
  int charsSinceName_ = 0;
  bool bodyOpened_ = false;  // '{' is the only character read since the last name
  std::string className_;    // "CapsuleVolume": the class whose declaration is being read
  std::string node_;         // "CapsuleVolume 'Head'": the node
  const ClassFields* fields_ = nullptr;
  std::string declaredType_;
  std::map<std::string, ClassFields> classes_;  // by class name
};

}  // namespace figment::guard
