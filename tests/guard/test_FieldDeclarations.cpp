// A node's `fields [ ... ]` declaration is checked against its class as Coin reads it: Coin
// added a field the class lacks to the field list every node of the class shares, and the
// next walk over another node of the class crashed (SIGSEGV).

#include <Inventor/SbName.h>
#include <Inventor/SoDB.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "guard/FieldDeclarations.h"

namespace test_FieldDeclarations {

using figment::guard::FieldDeclarations;

namespace {

// What FieldDeclarations says of the names and characters Coin reads for `tokens`: a word is a
// name, a single brace, bracket or comma a character. "" when it says nothing.
std::string problemIn(const std::vector<std::string>& tokens) {
  SoDB::init();
  FieldDeclarations declarations;
  for (const std::string& token : tokens) {
    if (token.size() == 1 && std::string("{}[],").find(token[0]) != std::string::npos) {
      declarations.seeChar(token[0]);
      continue;
    }
    if (std::string problem = declarations.seeName(SbName(token.c_str())); !problem.empty()) return problem;
  }
  return "";
}

}  // namespace

TEST(FieldDeclarations, PassesADeclarationOfTheClassesOwnFields) {
  EXPECT_EQ(problemIn({"Cube", "{", "fields", "[", "SFFloat", "width", ",", "SFFloat", "height", "]", "width"}), "");
  EXPECT_EQ(problemIn({"Cube", "{", "fields", "[", "]"}), "");
}

TEST(FieldDeclarations, RefusesAFieldTheClassDoesNotHave) {
  EXPECT_EQ(problemIn({"Cube", "{", "fields", "[", "SFFloat", "width", ",", "SFFloat", "wobble", "]"}),
            "Cube: fields [ SFFloat wobble ] declares a field Cube does not have");
  EXPECT_EQ(problemIn({"DEF", "Box", "Cube", "{", "fields", "[", "SFFloat", "r1e308", "]"}),
            "Cube 'Box': fields [ SFFloat r1e308 ] declares a field Cube does not have");
}

TEST(FieldDeclarations, RefusesAFieldDeclaredWithAnotherType) {
  EXPECT_EQ(problemIn({"Cube", "{", "fields", "[", "SFInt32", "width", "]"}),
            "Cube: fields [ SFInt32 width ] declares width an SFInt32, but it is an SFFloat");
}

TEST(FieldDeclarations, RefusesAKindOfFieldInANodesDeclaration) {
  EXPECT_EQ(problemIn({"Cube", "{", "fields", "[", "exposedField", "SFFloat", "width", "]"}),
            "Cube: fields [ exposedField ... ] gives a kind of field, which only PROTO interfaces and scripts declare");
}

TEST(FieldDeclarations, LooksOnlyAtADeclarationThatOpensANodesBody) {
  // A value named "fields" (an Info's string is not a name; a Label's is), a node whose class
  // Coin does not know (its own fields), and names after the declaration's end are not looked at.
  EXPECT_EQ(problemIn({"Label", "{", "label", "fields", "}", "SFFloat", "wobble"}), "");
  EXPECT_EQ(problemIn({"Frobnicator", "{", "fields", "[", "SFFloat", "wobble", "]"}), "");
  EXPECT_EQ(problemIn({"Cube", "{", "fields", "[", "SFFloat", "width", "]", "width", "SFFloat", "wobble"}), "");
}

}  // namespace test_FieldDeclarations
