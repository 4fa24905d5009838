#pragma once
// What SceneTextCheck watches for in a scene's token stream besides nesting and File
// includes: each watcher takes every token in turn, with the nesting depth after it, and
// says when it sees what Coin's reader would crash or hang on.

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "guard/SceneTokens.h"

namespace figment::guard {

// The DEF names whose node bodies are open at a point of the text. A USE of one of them
// puts a node inside its own definition: Coin makes it its own child or field value (a
// cycle), and when the inner node's read then fails, destroying it unrefs the outer node
// Coin is still reading, which frees it under the reader (found by fuzz_scene: a comment
// that swallowed a Mannequin's closing brace put `MannequinSkin { mannequin USE Model }`
// inside `DEF Model Mannequin`).
class OpenDefinitions {
 public:
  struct Definition {
    std::string name;
    int line = 0;   // of its DEF
    int depth = 0;  // of its body
  };

  // Takes every token in turn, with the nesting depth after it. Returns the open
  // definition a USE names, if any.
  const Definition* see(const Token& t, int depth);

 private:
  enum class Expect { kNothing, kDefName, kType, kBody, kUseName };
  Expect expect_ = Expect::kNothing;
  std::string pending_;
  int pendingLine_ = 0;
  std::vector<Definition> open_;                    // outermost first
  std::map<std::string, int, std::less<>> latest_;  // each name's last DEF line: a USE means that one
};

// The first URL of each EXTERNPROTO (VRML97: `EXTERNPROTO Name [ interface ] "url"`, or a list
// `[ "url", ... ]`), which Coin's fetch reads as a file the way it reads a File (a scene whose
// EXTERNPROTO named itself crashed figment-view, one naming /dev/zero hung it).
class ExternProtoUrls {
 public:
  // Takes every token in turn, with the nesting depth after it. Returns the EXTERNPROTO's name
  // when the token is its first URL, else null.
  const std::string* see(const Token& t, int depth);

 private:
  enum class Stage { kNone, kName, kInterface, kInInterface, kUrl, kFirstOfList };
  Stage stage_ = Stage::kNone;
  std::string name_;
  int interfaceDepth_ = 0;
};

// The PROTO definitions open at a point of the text. A prototype instantiated inside its own
// definition (its body, or its interface's default values, directly or through a PROTO defined
// inside it) is expanded by Coin without end: `PROTO A [ ] { Group { children [ A { } ] } }`
// crashed figment-view (SIGSEGV).
class OpenPrototypes {
 public:
  struct Prototype {
    std::string name;
    int line = 0;       // of its PROTO
    int depth = 0;      // the depth its PROTO lies at
    bool body = false;  // its body has opened (after the interface)
  };

  // Takes every token in turn, with the nesting depth after it. Returns the open prototype
  // the token instantiates (a '{' after its name), if any.
  const Prototype* see(const Token& t, int depth);

 private:
  enum class Expect { kNothing, kName, kInterface };
  Expect expect_ = Expect::kNothing;
  std::vector<Prototype> open_;  // outermost first
  std::string_view lastWord_;    // the word just before this token, if the token before was one
};

// The step of each TimeCounter and Counter engine, which Coin divides by (SIGFPE at 0, during
// the read already): `TimeCounter { step 0 }`, or 65536, which a short holds as 0, crashed
// figment-view. The step is read as Coin reads it, the whole number at the start of its word
// (`step 0.5` is 0). A step fed by a connection (`step = Calculator { ... }.oa`) is refused
// too, as its value is not known until Coin divides by it.
class CounterSteps {
 public:
  // Takes every token in turn, with the nesting depth after it. Returns a problem with the
  // step this token gives or connects ("TimeCounter { step 0 } divides by zero"), else "".
  std::string see(const Token& t, int depth);

 private:
  std::string stepValue(std::string_view word);  // the word (or rest of one) after `step`
  std::string connectedStep() const;
  enum class Expect { kNothing, kBody, kStepValue, kConnection };
  Expect expect_ = Expect::kNothing;
  std::string_view pendingType_;  // "TimeCounter", its body to open next
  std::string_view type_;         // the counter whose body is open
  int bodyDepth_ = -1;            // its depth; -1: none open
};

// The size each inline image declares (SFImage: `image 30000 30000 4 ...`, width, height and
// components; SFImage3: `images` with a depth too). Coin allocates the pixels before it reads
// them: 30000 x 30000 x 4 overflowed its size and threw std::bad_alloc (an out-of-memory
// report under AddressSanitizer). Each pixel is one number in the text, so a size the rest of
// the file cannot hold is refused.
class ImageSizes {
 public:
  explicit ImageSizes(size_t textSize) : textSize_(textSize) {}

  // Takes every token in turn. Returns a problem once an image's size is complete, else "".
  std::string see(const Token& t);

 private:
  size_t textSize_;
  std::string_view field_;  // the image field whose size is being read
  std::vector<long long> dimensions_;
  size_t wanted_ = 0;  // numbers in its size: 3, or 4 for SFImage3
};

// The watchers whose finds are refusals in themselves (an EXTERNPROTO's URL is an include
// instead): a node or prototype inside its own definition, a counter step of zero, an
// image larger than the file.
class ReaderHazards {
 public:
  explicit ReaderHazards(size_t textSize) : images_(textSize) {}

  // Takes every token in turn, with the nesting depth after it. Returns the first hazard
  // this token completes, as one line without its line number, else "".
  std::string see(const Token& t, int depth);

 private:
  OpenDefinitions definitions_;
  OpenPrototypes prototypes_;
  CounterSteps counterSteps_;
  ImageSizes images_;
};

}  // namespace figment::guard
