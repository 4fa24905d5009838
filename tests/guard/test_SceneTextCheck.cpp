// The look at a scene's text before Coin reads it: nesting and includes are bounded, a
// cycle of includes and a File naming a device are refused, each in one line; every
// shipped scene passes.

#include <Inventor/SoDB.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "guard/SceneTextCheck.h"
#include "support/TempDir.h"

using namespace figment::guard;
namespace fs = std::filesystem;

namespace {

const std::string kHeader = "#Inventor V2.1 ascii\n";

// `levels` levels: Separators one inside the other around a Cube.
std::string nested(int levels) {
  std::string text = kHeader;
  for (int i = 1; i < levels; ++i) text += "Separator {\n";
  text += "Cube { }\n";
  for (int i = 1; i < levels; ++i) text += "}\n";
  return text;
}

// "f3.iv" for ("f", 3).
std::string numbered(const char* stem, int i) {
  return std::string(stem).append(std::to_string(i)).append(".iv");
}

std::string including(const std::string& name) {
  return kHeader + "Separator {\n  File { name \"" + name + "\" }\n}\n";
}

class SceneTextCheckTest : public ::testing::Test {
 protected:
  void SetUp() override { SoDB::init(); }
  std::string write(const std::string& name, const std::string& text) const { return dir_.file(name, text); }
  figment::test::TempDir dir_;
};

}  // namespace

TEST_F(SceneTextCheckTest, PassesEveryShippedScene) {
  int count = 0;
  for (const auto& entry : fs::recursive_directory_iterator(FIGMENT_SOURCE_DIR "/scenes")) {
    if (entry.path().extension() != ".iv") continue;
    ++count;
    EXPECT_EQ(checkSceneText(entry.path().string()), "") << entry.path();
  }
  EXPECT_GT(count, 10);
}

TEST_F(SceneTextCheckTest, BoundsTheNestingDepth) {
  EXPECT_EQ(checkSceneText(write("at.iv", nested(kMaxNestingDepth))), "");
  // The Cube of 257 levels opens on line 258 (the header is line 1).
  EXPECT_EQ(checkSceneText(write("past.iv", nested(kMaxNestingDepth + 1))),
            "line 258: nesting depth 257 is more than 256");
}

TEST_F(SceneTextCheckTest, CountsBracketsButNothingInStringsOrComments) {
  const std::string quiet = kHeader + "Info { string \"{{{{ [[[[ \\\" {{{{\" }  # {{{{ [[[[\nSeparator { }\n";
  EXPECT_EQ(checkSceneText(write("quiet.iv", quiet)), "");
  std::string brackets = kHeader + "Separator {\n";
  for (int i = 0; i < kMaxNestingDepth; ++i) brackets += "[ ";
  EXPECT_EQ(checkSceneText(write("brackets.iv", brackets)), "line 3: nesting depth 257 is more than 256");
}

TEST_F(SceneTextCheckTest, CountsTheNestingAcrossIncludes) {
  // The File's body lies 200 levels deep: 56 levels more are allowed in the file it names.
  std::string outer = kHeader;
  for (int i = 0; i < 199; ++i) outer += "Separator {\n";
  outer += "File { name \"inner.iv\" }\n" + std::string(199, '}') + "\n";
  const std::string scene = write("outer.iv", outer);
  const std::string inner = write("inner.iv", nested(56));
  EXPECT_EQ(checkSceneText(scene), "");
  write("inner.iv", nested(57));
  EXPECT_EQ(checkSceneText(scene), "line 58: nesting depth 257 is more than 256 (in " + inner + ")");
}

TEST_F(SceneTextCheckTest, RefusesAFileThatIncludesItself) {
  const std::string scene = write("self.iv", including("self.iv"));
  EXPECT_EQ(checkSceneText(scene),
            "line 3: File { name \"self.iv\" } includes a file already being read: self.iv -> self.iv");
  // Unquoted, as an SFString may be written.
  EXPECT_NE(checkSceneText(write("bare.iv", kHeader + "File { name bare.iv }\n")).find("bare.iv -> bare.iv"),
            std::string::npos);
}

TEST_F(SceneTextCheckTest, RefusesTwoFilesThatIncludeEachOther) {
  const std::string a = write("a.iv", including("sub/b.iv"));
  const std::string b = write("sub/b.iv", including("../a.iv"));
  EXPECT_EQ(
      checkSceneText(a),
      "line 3: File { name \"../a.iv\" } includes a file already being read: a.iv -> b.iv -> a.iv (in " + b + ")");
}

TEST_F(SceneTextCheckTest, LooksBesideTheFileThatNamesTheInclude) {
  // sub/b.iv names "c.iv": sub/c.iv, not a c.iv beside the scene.
  write("a.iv", including("sub/b.iv"));
  write("sub/b.iv", including("c.iv"));
  write("sub/c.iv", kHeader + "Cube { }\n");
  write("c.iv", including("c.iv"));  // would be a cycle if found instead
  EXPECT_EQ(checkSceneText((dir_.path() / "a.iv").string()), "");
  // The same file twice, side by side, is no cycle.
  const std::string twice = kHeader + "Group { File { name \"sub/c.iv\" } File { name \"sub/c.iv\" } }\n";
  EXPECT_EQ(checkSceneText(write("twice.iv", twice)), "");
}

TEST_F(SceneTextCheckTest, BoundsTheIncludeDepth) {
  // fI.iv includes fI+1.iv: from f0.iv, f16.iv is 16 includes deep, f17.iv 17.
  for (int i = 0; i < 17; ++i) write(numbered("f", i), including(numbered("f", i + 1)));
  write("f17.iv", kHeader + "Cube { }\n");
  EXPECT_EQ(checkSceneText((dir_.path() / "f1.iv").string()), "");
  EXPECT_EQ(checkSceneText((dir_.path() / "f0.iv").string()),
            "line 3: File { name \"f17.iv\" } would be 17 includes deep, more than 16 (in " +
                (dir_.path() / "f16.iv").string() + ")");
}

TEST_F(SceneTextCheckTest, BoundsTheIncludesReadInAll) {
  // Each file includes the next one twice: 2 + 4 + ... + 2^10 = 2046 files to read.
  for (int i = 0; i < 10; ++i) {
    const std::string next = numbered("g", i + 1);
    write(numbered("g", i), kHeader + "Group { File { name \"" + next + "\" } File { name \"" + next + "\" } }\n");
  }
  write("g10.iv", kHeader + "Cube { }\n");
  EXPECT_NE(checkSceneText((dir_.path() / "g0.iv").string()).find("is include 1001, more than 1000 in all"),
            std::string::npos);
}

// Coin reads the first url of a VRMLInline (an Inline in VRML97) as a local file, as it reads
// a File's name: a scene inlining itself crashed figment-view (SIGSEGV), one inlining /dev/zero
// hung it (found trying every node of Coin's that reads a file). Inlines are includes.
TEST_F(SceneTextCheckTest, TakesAnInlinesUrlForAnInclude) {
  EXPECT_EQ(checkSceneText(write("self.iv", kHeader + "Separator {\n  VRMLInline { url \"self.iv\" }\n}\n")),
            "line 3: VRMLInline { url \"self.iv\" } includes a file already being read: self.iv -> self.iv");
  EXPECT_EQ(checkSceneText(
                write("zero.iv", kHeader + "VRMLInline {\n  bboxSize 1 1 1\n  url [ \"/dev/zero\", \"a.iv\" ]\n}\n")),
            "line 4: VRMLInline { url \"/dev/zero\" } is not a regular file");
  EXPECT_EQ(checkSceneText(write("vrml.wrl", "#VRML V2.0 utf8\nTransform { children Inline { url \"gone.wrl\" } }\n"))
                .rfind("line 2: Inline { url \"gone.wrl\" } not found: looked beside vrml.wrl", 0),
            0u);
  write("cube.wrl", "#VRML V2.0 utf8\nShape { geometry Box { } }\n");
  EXPECT_EQ(checkSceneText(write("ok.iv", kHeader + "Separator { VRMLInline { url [ \"cube.wrl\" ] } }\n")), "");
  EXPECT_EQ(checkSceneText(write("empty.iv", kHeader + "Separator { VRMLInline { url [ ] } Cube { } }\n")), "");
  // "url" outside an Inline's own body names nothing.
  EXPECT_EQ(checkSceneText(write("other.iv", kHeader + "Separator { Info { string \"url\" } }\n")), "");
}

// Coin's default EXTERNPROTO fetch reads the first URL (less any "#Name") as a file, as it reads
// a File: a VRML97 scene whose EXTERNPROTO named itself crashed figment-view (SIGSEGV), one
// naming /dev/zero hung it. The interface between the brackets names no file.
TEST_F(SceneTextCheckTest, TakesAnExternProtosFirstUrlForAnInclude) {
  const std::string vrml = "#VRML V2.0 utf8\n";
  EXPECT_EQ(checkSceneText(write("self.wrl", vrml + "EXTERNPROTO Foo [ ] \"self.wrl#Foo\"\nFoo { }\n")),
            "line 2: EXTERNPROTO Foo \"self.wrl#Foo\" includes a file already being read: self.wrl -> self.wrl");
  EXPECT_EQ(checkSceneText(write("zero.wrl", vrml + "EXTERNPROTO Foo [\n  field MFString names [ \"a\" ]\n]\n"
                                                    "[ \"/dev/zero\", \"b.wrl\" ]\nFoo { }\n")),
            "line 5: EXTERNPROTO Foo \"/dev/zero\" is not a regular file");
  write("protos.wrl", vrml + "PROTO Foo [ ] { Shape { geometry Box { } } }\n");
  EXPECT_EQ(checkSceneText(write("ok.wrl", vrml + "EXTERNPROTO Foo [ field SFFloat f ] \"protos.wrl#Foo\"\n"
                                                  "Transform { children Foo { } }\n")),
            "");
}

TEST_F(SceneTextCheckTest, RefusesWhatIsNotARegularFileOrNotThere) {
  EXPECT_EQ(checkSceneText(write("zero.iv", including("/dev/zero"))),
            "line 3: File { name \"/dev/zero\" } is not a regular file");
  // A file that is nowhere: the line says where it was looked for, in the order Coin looks.
  const std::string here = " (" + fs::absolute(dir_.path()).string() + ")";
  const std::string cwd = " (" + fs::current_path().string() + ")";
  EXPECT_EQ(checkSceneText(write("missing.iv", including("nothere.iv"))),
            "line 3: File { name \"nothere.iv\" } not found: looked beside missing.iv" + here +
                " and in the working directory" + cwd);
  fs::create_directory(dir_.path() / "folder.iv");  // SoInput passes folders over
  EXPECT_EQ(checkSceneText(write("folder.txt", including("folder.iv"))),
            "line 3: File { name \"folder.iv\" } not found: looked beside folder.txt" + here +
                " and in the working directory" + cwd);
  EXPECT_EQ(checkSceneText(write("absolute.iv", including("/nothere/x.iv"))),
            "line 3: File { name \"/nothere/x.iv\" } not found: no such file");
}

// What is not ASCII Inventor or VRML text cannot be checked, and Coin reads some of it without
// a bound: it decompresses gzip and bzip2 (a gzip of 100,000 nested Separators crashed
// figment-view), reads binary Inventor, and takes a headerless file beginning "MM" for 3D
// Studio, whose reader looped forever on 9 bytes (found by tests/fuzz/fuzz_scene; the input is
// in its corpus as 3ds-bytes-hang.iv). Each is refused, as the scene or as an include.
TEST_F(SceneTextCheckTest, RefusesWhatIsNotAsciiSceneText) {
  const std::string threeDs("MM\001\000o\226\215\000\006", 9);
  const std::string gzip("\x1f\x8b\x08\x00\x00\x00\x00\x00\x00\x03", 10);
  EXPECT_EQ(checkSceneText(write("a.iv", gzip)), "a gzip-compressed file: decompress it first");
  EXPECT_EQ(checkSceneText(write("b.iv", "BZh91AY&SY")), "a bzip2-compressed file: decompress it first");
  EXPECT_EQ(checkSceneText(write("c.iv", threeDs)),
            "a 3D Studio file (Coin's reader may never finish a damaged one): read the model through a MeshFile");
  EXPECT_EQ(checkSceneText(write("d.iv", "#Inventor V2.1 binary\n" + std::string(1000, '{'))),
            "a binary Inventor file: write it as ASCII first");
  EXPECT_EQ(checkSceneText(write("e.iv", "Separator { }\n")),
            "no Inventor or VRML header line (such as \"#Inventor V2.1 ascii\")");
  EXPECT_EQ(checkSceneText(write("f.iv", "")), "no Inventor or VRML header line (such as \"#Inventor V2.1 ascii\")");
  write("g.iv", threeDs);
  EXPECT_EQ(checkSceneText(write("h.iv", including("g.iv"))),
            "line 3: File { name \"g.iv\" } names a 3D Studio file (Coin's reader may never finish a damaged "
            "one): read the model through a MeshFile");
  EXPECT_EQ(checkSceneText(write("vrml.iv", "#VRML V2.0 utf8\nTransform { }\n")), "");
}

// A NUL byte was taken for a separator that nothing skipped: the tokenizer returned empty
// words forever and figment-view hung (found by tests/fuzz/fuzz_scene; the input is in its
// corpus as nul-byte-hang.iv). The bytes are now part of a word, and the text after them counts.
TEST_F(SceneTextCheckTest, ReadsPastNulBytes) {
  std::string text = nested(kMaxNestingDepth + 1);
  text.insert(kHeader.size(), std::string("Info\0\0 ", 7));
  EXPECT_EQ(checkSceneText(write("nul.iv", text)), "line 258: nesting depth " + std::to_string(kMaxNestingDepth + 1) +
                                                       " is more than " + std::to_string(kMaxNestingDepth));
}

// A node used inside its own definition is a cycle; when the inner node failed to read,
// destroying it unreffed the outer node Coin was still reading, a use after free (found by
// tests/fuzz/fuzz_scene; the input is in its corpus as use-inside-own-definition.iv).
TEST_F(SceneTextCheckTest, RefusesANodeUsedInsideItsOwnDefinition) {
  EXPECT_EQ(checkSceneText(write("self.iv", kHeader + "DEF A Separator {\n  Cube { }\n  USE A\n}\n")),
            "line 4: USE A inside the definition of A (DEF at line 2): a node cannot hold itself");
  EXPECT_EQ(checkSceneText(write("field.iv", kHeader + "DEF Model Group {\n  Separator {\n    MannequinSkin {\n"
                                                       "      mannequin USE Model\n    }\n  }\n}\n")),
            "line 5: USE Model inside the definition of Model (DEF at line 2): a node cannot hold itself");
}

TEST_F(SceneTextCheckTest, TakesAUseAfterItsDefinitionOrOfAnInnerRedefinition) {
  // After the body closes, and in a field's connection, as the shipped scenes do.
  EXPECT_EQ(checkSceneText(write("after.iv", kHeader + "Separator {\n  DEF A Cube { }\n  USE A\n}\n")), "");
  EXPECT_EQ(
      checkSceneText(write("connection.iv", kHeader + "DEF Model Group { }\nCoordinate3 {\n"
                                                      "  point = DEF Drape ClothEngine { body USE Model } . positions\n"
                                                      "}\n")),
      "");
  // The name DEFined again inside: USE means the inner node, which is closed.
  EXPECT_EQ(checkSceneText(write("inner.iv", kHeader + "DEF A Separator {\n  DEF A Cube { }\n  USE A\n}\n")), "");
  // Names in strings and comments are not nodes.
  EXPECT_EQ(checkSceneText(write("text.iv", kHeader + "DEF A Separator {\n  Info { string \"USE A\" }  # USE A\n}\n")),
            "");
}

// Coin expands a prototype instantiated inside its own definition without end: each of these
// crashed figment-view (SIGSEGV).
TEST_F(SceneTextCheckTest, RefusesAPrototypeInstantiatedInsideItsOwnDefinition) {
  const std::string vrml = "#VRML V2.0 utf8\n";
  EXPECT_EQ(
      checkSceneText(write("body.wrl", vrml + "PROTO Loop [ ] {\n  Group { children [ Loop { } ] }\n}\nLoop { }\n")),
      "line 3: Loop { } inside the definition of PROTO Loop (at line 2): a prototype cannot hold itself");
  EXPECT_EQ(checkSceneText(write("default.wrl", vrml + "PROTO Loop [ field SFNode n Loop { } ] { Group { } }\n")),
            "line 2: Loop { } inside the definition of PROTO Loop (at line 2): a prototype cannot hold itself");
  EXPECT_EQ(checkSceneText(write("inner.wrl", vrml + "PROTO Outer [ ] {\n  PROTO Inner [ ] { Outer { } }\n"
                                                     "  Group { children [ Inner { } ] }\n}\n")),
            "line 3: Outer { } inside the definition of PROTO Outer (at line 2): a prototype cannot hold itself");
  // One prototype in another's body, or used after its definition closed, is fine.
  EXPECT_EQ(checkSceneText(write(
                "ok.wrl", vrml + "PROTO Ball [ field SFFloat r 1 ] { Shape { geometry Sphere { radius IS r } } }\n"
                                 "PROTO Two [ ] { Group { children [ Ball { } Ball { r 2 } ] } }\n"
                                 "Two { } Ball { }\n")),
            "");
}

// Coin divides by a TimeCounter's or Counter's step as the text is read: a step of 0 raised
// SIGFPE in figment-view.
TEST_F(SceneTextCheckTest, RefusesACounterStepOfZero) {
  const auto counter = [this](const std::string& engine) {
    return checkSceneText(write("counter.iv",
                                "#Inventor V2.1 ascii\nTranslation {\n  translation = ComposeVec3f {\n"
                                "    x = " +
                                    engine + " .output } .vector\n}\n"));
  };
  EXPECT_EQ(counter("TimeCounter { step 0 }"),
            "line 4: TimeCounter { step 0 } divides by zero: the step must not be 0 (or a multiple of 65536)");
  EXPECT_EQ(counter("Counter { min 0 max 5 step 65536 reset 2 }"),
            "line 4: Counter { step 65536 } divides by zero: the step must not be 0 (or a multiple of 65536)");
  EXPECT_EQ(counter("DEF Ticks TimeCounter { step 0x0 }"),
            "line 4: TimeCounter { step 0x0 } divides by zero: the step must not be 0 (or a multiple of 65536)");
  EXPECT_EQ(counter("TimeCounter { step = Calculator { expression \"oa = 0\" } .oa }"),
            "line 4: TimeCounter { step = ... } takes its step from a connection: Coin divides by the step, and a "
            "step of 0 crashes it; give the step as a number");
  EXPECT_EQ(counter("TimeCounter { min 0 max 10 step 2 }"), "");
  EXPECT_EQ(counter("TimeCounter { }"), "");  // the default step is 1
  // Coin reads a whole number from the start of a word and leaves the rest: `step 0.5` sets 0
  // (SIGFPE; found by fuzz_scene as `step 0` and a stray byte).
  EXPECT_EQ(counter("TimeCounter { step 0.5 }"),
            "line 4: TimeCounter { step 0.5 } divides by zero: Coin reads it as 0; the step must not be 0 (or a "
            "multiple of 65536)");
  EXPECT_EQ(counter("Counter { step 08 }"),
            "line 4: Counter { step 08 } divides by zero: Coin reads it as 0; the step must not be 0 (or a "
            "multiple of 65536)");
  EXPECT_EQ(counter("TimeCounter { step 2.5 }"), "");
  // A connection glued to the name or the value is a connection all the same.
  const std::string connected = "line 4: TimeCounter { step = ... } takes its step from a connection";
  EXPECT_EQ(counter("TimeCounter { step=Calculator { expression \"oa = 0\" } .oa }").substr(0, connected.size()),
            connected);
  EXPECT_EQ(counter("TimeCounter { step 1=Calculator { expression \"oa = 0\" } .oa }").substr(0, connected.size()),
            connected);
  EXPECT_EQ(counter("TimeCounter { step 1 =Calculator { expression \"oa = 0\" } .oa }").substr(0, connected.size()),
            connected);
}

// Coin allocates an inline image's pixels before reading them: 30000 x 30000 x 4 overflowed
// its size and threw std::bad_alloc (an out-of-memory report under AddressSanitizer).
TEST_F(SceneTextCheckTest, RefusesAnImageLargerThanTheFileHolds) {
  const auto scene = [this](const std::string& body) {
    return checkSceneText(write("image.iv", "#Inventor V2.1 ascii\nSeparator {\n  " + body + "\n  Cube { }\n}\n"));
  };
  EXPECT_EQ(scene("Texture2 { image 30000 30000 4 0 }"),
            "line 3: image 30000 x 30000 declares 900000000 pixels, more than the 18 bytes left in the file hold "
            "(a number each)");
  EXPECT_EQ(scene("Texture3 { images 100 100 100 3 0xff0000 }"),
            "line 3: images 100 x 100 x 100 declares 1000000 pixels, more than the 25 bytes left in the file hold "
            "(a number each)");
  // Coin reads 4 from `4.5` and allocates before the rest of the word fails its read.
  EXPECT_EQ(scene("Texture2 { image 30000 30000 4.5 0 }"),
            "line 3: image 30000 x 30000 declares 900000000 pixels, more than the 18 bytes left in the file hold "
            "(a number each)");
  EXPECT_EQ(scene("Texture2 { image 2 1 3 0xff0000 0x00ff00 }"), "");
  EXPECT_EQ(scene("Texture2 { image 0 0 0 }"), "");  // empty
}
