// The watchers of a scene's token stream, fed the tokens of literal texts with the nesting
// depth as SceneTextCheck keeps it: a USE inside its own DEF's body, an EXTERNPROTO's first
// URL, a PROTO instantiated inside its own definition.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "guard/SceneTextWatchers.h"
#include "guard/SceneTokens.h"

using namespace figment::guard;

namespace {

// Feeds every token of `text` to `watch` with the depth after it; returns what it said, in
// order, as "line: text" for each answer.
template <class Watcher, class Say>
std::vector<std::string> watched(const std::string& text, Watcher& watcher, Say say) {
  Tokenizer tokens(text);
  std::vector<std::string> said;
  int depth = 0;
  for (Token t = tokens.next(); t.kind != Token::kEnd; t = tokens.next()) {
    depth += t.kind == Token::kOpen ? 1 : t.kind == Token::kClose ? -1 : 0;
    if (const auto* answer = watcher.see(t, depth)) said.push_back(std::to_string(t.line) + ": " + say(*answer));
  }
  return said;
}

TEST(SceneTextWatchers, AUseInsideItsOwnDefinitionIsSeen) {
  const std::string text = "#Inventor V2.1 ascii\nSeparator {\n  DEF A Group {\n    USE A\n  }\n  USE A\n}\n";
  OpenDefinitions definitions;
  const auto said = watched(text, definitions, [](const OpenDefinitions::Definition& d) {
    return d.name + " of line " + std::to_string(d.line);
  });
  EXPECT_EQ(said, std::vector<std::string>{"4: A of line 3"});  // the USE after the body closed is fine
}

TEST(SceneTextWatchers, AnExternProtosFirstUrlIsSeen) {
  const std::string text = "#VRML V2.0 utf8\nEXTERNPROTO Leg [ field SFFloat size ] [ \"a.wrl\", \"b.wrl\" ]\n";
  ExternProtoUrls urls;
  const auto said = watched(text, urls, [](const std::string& name) { return name; });
  EXPECT_EQ(said, std::vector<std::string>{"2: Leg"});
}

TEST(SceneTextWatchers, APrototypeInstantiatedInsideItselfIsSeen) {
  const std::string text =
      "#VRML V2.0 utf8\nPROTO A [ ] { Group { children [ A { } ] } }\nPROTO B [ ] { Group { } }\nB { }\n";
  OpenPrototypes prototypes;
  const auto said = watched(text, prototypes, [](const OpenPrototypes::Prototype& p) { return p.name; });
  EXPECT_EQ(said, std::vector<std::string>{"2: A"});
}

}  // namespace
